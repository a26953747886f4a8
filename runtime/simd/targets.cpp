#include "runtime/simd/targets.hpp"

#include <atomic>

#if HWY_ARCH_X86
#include <cpuid.h>
#endif

namespace vbim::simd {
namespace {

#if HWY_ARCH_X86
// CPUID leaves, sub-leaves and bits: Intel 64 and IA-32 Architectures Software Developer's Manual,
// vol. 2A, "CPUID"; XCR0's state bits: vol. 1, 13.1. The groups per target are Highway 1.0.3's
// (hwy/targets.cc), plus AVX512CD and GFNI, which later versions of Highway require: a CPU that lacks
// them keeps the next target down, never one it cannot run.
struct Registers {
  std::uint32_t a = 0, b = 0, c = 0, d = 0;
};

Registers cpuid(std::uint32_t leaf, std::uint32_t subleaf) {
  Registers r;
  __cpuid_count(leaf, subleaf, r.a, r.b, r.c, r.d);
  return r;
}

bool has(std::uint32_t reg, int bit) {
  return ((reg >> bit) & 1u) != 0;
}

std::uint32_t xcr0() {
  std::uint32_t lo = 0, hi = 0;
  __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
  return lo;
}

std::int64_t detectTargets() {
  std::int64_t targets = HWY_SCALAR | HWY_EMU128;
  const std::uint32_t maxLeaf = cpuid(0, 0).a;
  if (maxLeaf < 1) return targets;
  const Registers l1 = cpuid(1, 0);
  const bool ssse3 = has(l1.d, 25) && has(l1.d, 26) && has(l1.c, 0) && has(l1.c, 9);           // SSE SSE2 SSE3 SSSE3
  const bool sse4 = ssse3 && has(l1.c, 19) && has(l1.c, 20) && has(l1.c, 1) && has(l1.c, 25);  // 4.1 4.2 CLMUL AES
  const Registers l7 = maxLeaf >= 7 ? cpuid(7, 0) : Registers{};
  const bool lzcnt = cpuid(0x80000000u, 0).a >= 0x80000001u && has(cpuid(0x80000001u, 0).c, 5);
  // AVX FMA F16C from leaf 1; AVX2 BMI BMI2 from leaf 7.
  const bool avx2 =
      sse4 && has(l1.c, 28) && has(l1.c, 12) && has(l1.c, 29) && has(l7.b, 5) && has(l7.b, 3) && has(l7.b, 8) && lzcnt;
  // AVX512 F DQ CD BW VL.
  const bool avx3 = avx2 && has(l7.b, 16) && has(l7.b, 17) && has(l7.b, 28) && has(l7.b, 30) && has(l7.b, 31);
  // VBMI VBMI2 GFNI VAES VPCLMULQDQ VNNI BITALG VPOPCNTDQ.
  const bool avx3dl = avx3 && has(l7.c, 1) && has(l7.c, 6) && has(l7.c, 8) && has(l7.c, 9) && has(l7.c, 10) &&
                      has(l7.c, 11) && has(l7.c, 12) && has(l7.c, 14);
  if (ssse3) targets |= HWY_SSSE3;
  if (sse4) targets |= HWY_SSE4;
  // The wider registers count only if the OS saves them on a context switch: OSXSAVE, then XCR0's
  // SSE and AVX state (bits 1, 2) and the AVX-512 opmask and upper ZMM state (bits 5, 6, 7).
  const std::uint32_t os = has(l1.c, 27) ? xcr0() : 0;
  const bool ymm = (os & 0x6u) == 0x6u;
  const bool zmm = ymm && (os & 0xE0u) == 0xE0u;
  if (avx2 && ymm) targets |= HWY_AVX2;
  if (avx3 && zmm) targets |= HWY_AVX3;
  if (avx3dl && zmm) targets |= HWY_AVX3_DL;
  return targets;
}
#else
// Elsewhere the targets the compiler flags already guarantee.
std::int64_t detectTargets() {
  return HWY_SCALAR | HWY_EMU128 | HWY_ENABLED_BASELINE;
}
#endif

std::int64_t cpuTargets() {
  static const std::int64_t targets = detectTargets();
  return targets;
}

std::atomic<std::int64_t> forced{0};

struct Choice {
  hwy::ChosenTarget chosen;
  Choice() { chosen.Update(cpuTargets()); }
};

Choice& choice() {
  static Choice c;
  return c;
}

}  // namespace

std::int64_t supportedTargets() {
  const std::int64_t f = forced.load(std::memory_order_relaxed);
  return f != 0 ? f : cpuTargets();
}

void setTargetsForTest(std::int64_t targets) {
  forced.store(targets, std::memory_order_relaxed);
  choice().chosen.Update(supportedTargets());
}

void forEachTarget(std::int64_t generated, const std::function<void(std::int64_t target)>& fn) {
  struct Restore {
    ~Restore() { setTargetsForTest(0); }
  } restore;
  const std::int64_t runnable = cpuTargets() & generated;
  for (std::int64_t rest = runnable; rest != 0; rest &= rest - 1) {
    const std::int64_t target = rest & -rest;  // Highway numbers better targets with lower bits
    setTargetsForTest(target);
    fn(target);
  }
}

const hwy::ChosenTarget& chosenTarget() {
  return choice().chosen;
}

}  // namespace vbim::simd
