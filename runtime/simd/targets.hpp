// Which of Highway's instruction-set targets this CPU runs, and the dispatch tables that use the
// answer. The SIMD kernels (gs/simd, ipu/simd) are Highway code compiled once per target; this is how
// a call picks one at run time.
//
// Why not Highway's own HWY_EXPORT / HWY_DYNAMIC_DISPATCH: they ask libhwy.so
// (hwy::SupportedTargets, hwy::GetChosenTarget), and loading libhwy.so 1.0.3 runs a static
// initializer that calibrates its benchmark timer (hwy::platform::TimerResolution, a loop of rdtsc
// pairs): 4-6 ms of CPU at every start of every program that links it, measured with `perf stat` on
// an empty program with and without -lhwy on the 2-vCPU Intel Xeon of 2026-12-05, where a 60 s play
// of the demo's stream takes about 45 ms (bench/sweep/startup.sh times vbim's start-up). The kernels
// and the table layout still come from Highway's headers (HWY_CHOOSE_TARGET_LIST, hwy::ChosenTarget,
// both header-only), so nothing links libhwy.so.
#pragma once

#include <hwy/targets.h>

#include <cstdint>
#include <functional>

namespace vbim::simd {

// The Highway target bits (HWY_AVX3, HWY_AVX2, HWY_SSE4, HWY_SSSE3, plus HWY_SCALAR and HWY_EMU128,
// which every CPU runs) of this CPU, from CPUID and the OS's XCR0 as Highway 1.0.3 reads them
// (hwy/targets.cc: the same feature groups), read once. A forced set (setTargetsForTest) replaces it.
std::int64_t supportedTargets();

// Forces the targets every dispatch table uses from the next call on (0: the CPU's again). For tests
// and benchmarks that run each target in turn; not thread-safe against calls in flight.
void setTargetsForTest(std::int64_t targets);

// Runs fn(target) once for each target in `generated` (pass HWY_TARGETS) that this CPU runs, best
// first, with that target forced, then gives the CPU's choice back (also when fn throws).
void forEachTarget(std::int64_t generated, const std::function<void(std::int64_t target)>& fn);

// The index into a VBIM_SIMD_EXPORT table: Highway's own layout (hwy::ChosenTarget::GetIndex).
const hwy::ChosenTarget& chosenTarget();

}  // namespace vbim::simd

// In the HWY_ONCE part of a kernel file, after <hwy/highway.h>, at the namespace of FUNC:
//   VBIM_SIMD_EXPORT(FUNC);   a table with FUNC of every target compiled in this file
//   VBIM_SIMD_DISPATCH(FUNC)  the one chosenTarget() picks, as a function
// Highway's HWY_EXPORT has the same layout; its first entry, which initialises libhwy's choice on
// the first call, is never taken here: chosenTarget() is initialised before its first use.
#define VBIM_SIMD_EXPORT(FUNC)                                                                                       \
  static decltype(&HWY_STATIC_DISPATCH(FUNC)) const HWY_CONCAT(FUNC, VbimSimdTable)[HWY_MAX_DYNAMIC_TARGETS + 2] = { \
      nullptr, HWY_CHOOSE_TARGET_LIST(FUNC), HWY_CHOOSE_FALLBACK(FUNC)}
#define VBIM_SIMD_DISPATCH(FUNC) (*(HWY_CONCAT(FUNC, VbimSimdTable)[::vbim::simd::chosenTarget().GetIndex()]))
