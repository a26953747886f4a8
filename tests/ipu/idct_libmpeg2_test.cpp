// The libmpeg2-family inverse DCTs (ipu/idct_libmpeg2.hpp) and their scalar kernels against their
// references: IdctKind::Libmpeg2 against Debian's libmpeg2 itself (its C IDCT, selected by
// mpeg2_accel(0)), both the intra (copy) and the non-intra (add) paths; IdctKind::Pcsx2 against the
// known answers computed from a reading of PCSX2's IPU (tests/ipu/data/idct_pcsx2_known_answers.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

extern "C" {
#include <mpeg2.h>
// The IDCT entry points mpeg2_accel() selects (libmpeg2's internal interface, exported by the
// library): coefficients scaled by 16 in libmpeg2's permuted order; the block is zeroed on return.
extern void (*mpeg2_idct_copy)(std::int16_t* block, std::uint8_t* dest, int stride);
extern void (*mpeg2_idct_add)(int last, std::int16_t* block, std::uint8_t* dest, int stride);
}

#include "ipu/idct_libmpeg2.hpp"
#include "ipu/kernels.hpp"
#include "tests/ipu/support/idct_blocks.hpp"

namespace vbim::ipu {
namespace {

using testing::IdctBlock;
using testing::Lcg;

// libmpeg2's C IDCT reads coefficient (v, u) at perm(v) * 8 + perm(u), scaled by 16.
int perm(int k) {
  return (k >> 1) | ((k & 1) << 2);
}

void initLibmpeg2() {
  static const bool once = [] {
    EXPECT_EQ(mpeg2_accel(0), 0u) << "libmpeg2 picked accelerated code: its C IDCT is the reference";
    return true;
  }();
  (void)once;
}

void toLibmpeg2(const std::int16_t* raster, std::int16_t* out) {
  for (int v = 0; v < 8; ++v)
    for (int u = 0; u < 8; ++u) out[perm(v) * 8 + perm(u)] = static_cast<std::int16_t>(raster[8 * v + u] * 16);
}

// libmpeg2 clips through a table covering -3840..4095: a result outside it is undefined behaviour
// in the reference itself, so such blocks are not compared (counted instead).
bool inClipTable(const std::int16_t* r, const std::uint8_t* dst = nullptr) {
  for (int i = 0; i < 64; ++i) {
    const int v = r[i] + (dst ? dst[i] : 0);
    if (v < -3840 || v > 4095) return false;
  }
  return true;
}

std::uint8_t clampPixel(int v) {
  return static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
}

TEST(IpuIdctLibmpeg2, MatchesLibmpeg2CopyAndAdd) {
  initLibmpeg2();
  const IdctKernels& k = scalarKernels().idctOf(IdctKind::Libmpeg2);
  Lcg rng{2029};
  int compared = 0, skipped = 0, shortcuts = 0;
  for (int t = 0; t < 300000; ++t) {
    const IdctBlock b = testing::makeIdctBlock(t, rng);
    std::int16_t ours[64];
    idctLibmpeg2(b.c, ours);
    if (!inClipTable(ours)) {
      ++skipped;
      continue;
    }
    ++compared;
    // Intra: the function clamped, the kernel, and libmpeg2's copy.
    alignas(16) std::int16_t lb[64];
    toLibmpeg2(b.c, lb);
    std::uint8_t ref[64], kern[64];
    mpeg2_idct_copy(lb, ref, 8);
    k.copy(b.c, b.rows, b.cols, kern, 8);
    for (int i = 0; i < 64; ++i) {
      ASSERT_EQ(clampPixel(ours[i]), ref[i]) << "block " << t << " sample " << i;
      ASSERT_EQ(kern[i], ref[i]) << "block " << t << " sample " << i;
    }
    // Non-intra: added to a random prediction; last = 129 when only the first scan coefficient
    // was coded (the DC-only blocks), which takes libmpeg2's DC shortcut.
    std::uint8_t pred[64], refAdd[64], kernAdd[64];
    for (int i = 0; i < 64; ++i) pred[i] = static_cast<std::uint8_t>(rng.below(256));
    if (!inClipTable(ours, pred)) continue;
    const bool firstOnly = (b.rows & kIdctFirstOnly) != 0;
    shortcuts += firstOnly && nonIntraDcShortcut(b.c[0]);
    std::copy(pred, pred + 64, refAdd);
    std::copy(pred, pred + 64, kernAdd);
    toLibmpeg2(b.c, lb);
    mpeg2_idct_add(firstOnly ? 129 : 63, lb, refAdd, 8);
    k.add(b.c, b.rows, b.cols, kernAdd, 8);
    for (int i = 0; i < 64; ++i) ASSERT_EQ(kernAdd[i], refAdd[i]) << "add, block " << t << " sample " << i;
  }
  std::printf("libmpeg2 C IDCT: %d blocks identical (copy and add, %d DC shortcuts), %d outside its clip table\n",
              compared, shortcuts, skipped);
  EXPECT_GT(shortcuts, 10000);
}

// Every DC value and toggle sign, in both libmpeg2 paths.
TEST(IpuIdctLibmpeg2, EveryDcValue) {
  initLibmpeg2();
  const IdctKernels& k = scalarKernels().idctOf(IdctKind::Libmpeg2);
  for (int dc = -2048; dc <= 2047; ++dc)
    for (int toggle : {0, 1, -1}) {
      std::int16_t c[64] = {};
      c[0] = static_cast<std::int16_t>(dc);
      c[63] = static_cast<std::int16_t>(toggle);
      const unsigned rows = 1u | (toggle ? kIdctToggleOnly : 0u);
      alignas(16) std::int16_t lb[64];
      std::uint8_t ref[64], kern[64];
      toLibmpeg2(c, lb);
      mpeg2_idct_copy(lb, ref, 8);
      k.copy(c, rows, 1, kern, 8);
      for (int i = 0; i < 64; ++i) ASSERT_EQ(kern[i], ref[i]) << "dc " << dc << " toggle " << toggle;
      for (int pred : {0, 77, 128, 255}) {
        std::uint8_t refAdd[64], kernAdd[64];
        std::fill(refAdd, refAdd + 64, static_cast<std::uint8_t>(pred));
        std::fill(kernAdd, kernAdd + 64, static_cast<std::uint8_t>(pred));
        toLibmpeg2(c, lb);
        mpeg2_idct_add(129, lb, refAdd, 8);
        k.add(c, rows | kIdctFirstOnly, 1, kernAdd, 8);
        for (int i = 0; i < 64; ++i) ASSERT_EQ(kernAdd[i], refAdd[i]) << "dc " << dc << " toggle " << toggle;
      }
    }
}

TEST(IpuIdctPcsx2, MatchesKnownAnswers) {
  const char* root = std::getenv("VBIM_SOURCE_DIR");
  ASSERT_NE(root, nullptr) << "VBIM_SOURCE_DIR names the source tree";
  std::ifstream f(std::string(root) + "/tests/ipu/data/idct_pcsx2_known_answers.txt");
  ASSERT_TRUE(f) << "cannot open the known answers";
  const IdctKernels& k = scalarKernels().idctOf(IdctKind::Pcsx2);
  std::string line;
  int blocks = 0;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::int16_t c[64], want[64];
    std::string bar;
    unsigned rows = 1, cols = 1;
    for (int i = 0; i < 64; ++i) {
      int v = 0;
      in >> v;
      c[i] = static_cast<std::int16_t>(v);
      if (v != 0) {
        rows |= 1u << (i >> 3);
        cols |= 1u << (i & 7);
      }
    }
    in >> bar;
    ASSERT_EQ(bar, "|") << "line of block " << blocks;
    for (int i = 0; i < 64; ++i) {
      int v = 0;
      in >> v;
      want[i] = static_cast<std::int16_t>(v);
    }
    ASSERT_TRUE(in) << "short line of block " << blocks;
    std::int16_t got[64];
    idctPcsx2(c, got);
    std::uint8_t pix[64], add[64];
    k.copy(c, rows, cols, pix, 8);
    std::fill(add, add + 64, std::uint8_t{128});
    k.add(c, rows, cols, add, 8);
    for (int i = 0; i < 64; ++i) {
      ASSERT_EQ(got[i], want[i]) << "block " << blocks << " sample " << i;
      ASSERT_EQ(pix[i], clampPixel(want[i])) << "block " << blocks << " sample " << i;
      ASSERT_EQ(add[i], clampPixel(128 + want[i])) << "block " << blocks << " sample " << i;
    }
    ++blocks;
  }
  EXPECT_EQ(blocks, 400);
}

// The two forms are different functions: they differ in the last bit on a few percent of blocks.
TEST(IpuIdctPcsx2, DiffersFromLibmpeg2InTheLastBit) {
  Lcg rng{5};
  int differ = 0, blocks = 0, maxAbs = 0;
  for (int t = 0; t < 70000; ++t) {
    if (t % 7 == 5 || t % 7 == 3 || t % 7 == 0) continue;  // natural ranges only: sparse, DC only, small dense
    const IdctBlock b = testing::makeIdctBlock(t, rng);
    std::int16_t p[64], l[64];
    idctPcsx2(b.c, p);
    idctLibmpeg2(b.c, l);
    bool d = false;
    for (int i = 0; i < 64; ++i) {
      d |= p[i] != l[i];
      maxAbs = std::max(maxAbs, std::abs(p[i] - l[i]));
    }
    differ += d;
    ++blocks;
  }
  std::printf("pcsx2 vs libmpeg2: %d of %d blocks differ (%.2f %%), by at most %d\n", differ, blocks,
              100.0 * differ / blocks, maxAbs);
  EXPECT_GT(differ, 0);
  EXPECT_LE(maxAbs, 1);
}

}  // namespace
}  // namespace vbim::ipu
