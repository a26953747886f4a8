// The scalar blend against the GS formula, written here independently: floor division by 128
// spelled out, then COLCLAMP. Every (Cs, Cd, FIX) triple, both COLCLAMP modes, both alpha modes.
#include "gs/blend.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "gs/error.hpp"

namespace vbim::gs {
namespace {

bool isSampleFix(int fix) {
  return fix % 17 == 0 || fix == 1 || fix == 64 || fix == 127 || fix == 128 || fix == 129;
}

int floorDiv128(int a) {
  return a >= 0 ? a / 128 : -((-a + 127) / 128);
}

int formula(int cs, int cd, int fix, ColClamp c) {
  const int v = floorDiv128((cs - cd) * fix) + cd;
  if (c == ColClamp::Clamp) return v < 0 ? 0 : (v > 255 ? 255 : v);
  return ((v % 256) + 256) % 256;
}

// 65,536 pixels whose R channel runs through every (Cs, Cd) pair, G through every pair in the other
// order, B through a third pairing; alpha differs between source and destination.
void allPairs(std::vector<std::uint8_t>& src, std::vector<std::uint8_t>& dst) {
  src.resize(65536 * 4);
  dst.resize(65536 * 4);
  for (int i = 0; i < 65536; ++i) {
    const int a = i & 0xFF, b = i >> 8;
    src[4 * i + 0] = static_cast<std::uint8_t>(a), dst[4 * i + 0] = static_cast<std::uint8_t>(b);
    src[4 * i + 1] = static_cast<std::uint8_t>(b), dst[4 * i + 1] = static_cast<std::uint8_t>(a);
    src[4 * i + 2] = static_cast<std::uint8_t>(a ^ b), dst[4 * i + 2] = static_cast<std::uint8_t>(b);
    src[4 * i + 3] = static_cast<std::uint8_t>(i * 7), dst[4 * i + 3] = static_cast<std::uint8_t>(i * 13);
  }
}

// One pass over all 16.7 M triples checks the channel function against the formula in both
// COLCLAMP modes, the fixed-point predicate and the one-step bound (plain ifs: millions of gtest
// assertions would dominate the run time under the sanitizers).
TEST(Blend, ChannelFormulaFixedPointAndStepBoundForEveryTriple) {
  for (int fix = 0; fix < 256; ++fix) {
    for (int cs = 0; cs < 256; ++cs) {
      for (int cd = 0; cd < 256; ++cd) {
        const int clamp = blendChannel(cs, cd, fix, ColClamp::Clamp);
        const int wrap = blendChannel(cs, cd, fix, ColClamp::Wrap);
        const bool ok = clamp == formula(cs, cd, fix, ColClamp::Clamp) &&
                        wrap == formula(cs, cd, fix, ColClamp::Wrap) && isFixedPoint(cs, cd, fix) == (clamp == cd) &&
                        std::abs(clamp - cd) <= maxStep(std::abs(cs - cd), fix);
        if (!ok) {
          FAIL() << "Cs " << cs << " Cd " << cd << " FIX " << fix << ": clamp " << clamp << " wrap " << wrap
                 << " formula " << formula(cs, cd, fix, ColClamp::Clamp) << "/" << formula(cs, cd, fix, ColClamp::Wrap);
        }
      }
    }
  }
}

TEST(Blend, ClampAndWrapDifferOnlyWhenFixExceeds128) {
  // Some examples the formula gives: 0 + floor(255 * 255 / 128) = 508 -> 255 clamped, 252 wrapped.
  EXPECT_EQ(blendChannel(255, 0, 255, ColClamp::Clamp), 255);
  EXPECT_EQ(blendChannel(255, 0, 255, ColClamp::Wrap), 508 & 0xFF);
  EXPECT_EQ(blendChannel(0, 255, 255, ColClamp::Clamp), 0);
  EXPECT_EQ(blendChannel(0, 255, 255, ColClamp::Wrap), 2);  // 255 - 509 = -254 -> 2
  // Floor, not truncation: (10 - 11) * 64 = -64 -> floor(-0.5) = -1.
  EXPECT_EQ(blendChannel(10, 11, 64, ColClamp::Clamp), 10);
  EXPECT_EQ(blendChannel(11, 10, 64, ColClamp::Clamp), 10);  // floor(0.5) = 0: stays
  int differ = 0;
  for (int fix = 0; fix < 256; ++fix) {
    for (int cs = 0; cs < 256; ++cs) {
      for (int cd = 0; cd < 256; ++cd) {
        const bool same = blendChannel(cs, cd, fix, ColClamp::Clamp) == blendChannel(cs, cd, fix, ColClamp::Wrap);
        if (fix <= 128 && !same) FAIL() << cs << " " << cd << " " << fix;
        differ += same ? 0 : 1;
      }
    }
  }
  EXPECT_GT(differ, 0);
}

TEST(Blend, ScalarSpanMatchesFormulaOnEveryTripleBothModes) {
  std::vector<std::uint8_t> src, dst0;
  allPairs(src, dst0);
  for (ColClamp cc : {ColClamp::Clamp, ColClamp::Wrap}) {
    for (AlphaWrite aw : {AlphaWrite::Source, AlphaWrite::Keep}) {
      for (int fix = 0; fix < 256; ++fix) {
        // Alpha handling does not depend on FIX except across the 128 boundary: every FIX with the
        // hardware's alpha rule, a spread of them with FBMSK keeping Ad (keeps the sanitizer run short).
        if (aw == AlphaWrite::Keep && !isSampleFix(fix)) continue;
        std::vector<std::uint8_t> dst = dst0;
        const BlendSpec spec = makeBlendSpec(fix, cc, aw);
        const int delta = blendSpanDeltaScalar(dst.data(), src.data(), 65536, spec);
        std::vector<std::uint8_t> dst2 = dst0;
        blendSpanScalar(dst2.data(), src.data(), 65536, spec);
        ASSERT_EQ(dst, dst2);
        int expectDelta = 0;
        std::vector<std::uint8_t> want(dst0.size());
        for (std::size_t i = 0; i < want.size(); ++i) {
          want[i] = static_cast<std::uint8_t>((i % 4 == 3) ? (aw == AlphaWrite::Source ? src[i] : dst0[i])
                                                           : formula(src[i], dst0[i], fix, cc));
          expectDelta = std::max(expectDelta, std::abs(want[i] - dst0[i]));
        }
        ASSERT_EQ(dst, want) << "fix " << fix;
        ASSERT_EQ(delta, expectDelta);
      }
    }
  }
}

// Repeated blending toward a fixed target T: from above it always reaches T (every step is at least
// -1 by floor); from below it stops anywhere in [T - stallBand, T]. The asymmetry is the floor.
TEST(Blend, RepeatedBlendingConvergesAsymmetrically) {
  for (int fix : {1, 2, 3, 5, 16, 32, 48, 64, 96, 127, 128}) {
    bool stoppedShort = false;
    for (int target = 0; target < 256; ++target) {
      for (int start = 0; start < 256; ++start) {
        int d = start, steps = 0;
        while (!isFixedPoint(target, d, fix)) {
          const int next = blendChannel(target, d, fix, ColClamp::Clamp);
          ASSERT_NE(next, d);
          // Never overshoots the target for FIX <= 128.
          if (start <= target) {
            ASSERT_LE(next, target);
          }
          if (start >= target) {
            ASSERT_GE(next, target);
          }
          d = next;
          ASSERT_LT(++steps, 4000) << "no convergence: fix " << fix;
        }
        if (start >= target) {
          ASSERT_EQ(d, target) << "from above: fix " << fix << " start " << start << " target " << target;
        } else {
          ASSERT_GE(d, target - stallBand(fix)) << "fix " << fix;
          ASSERT_LE(d, target);
          stoppedShort |= d < target;
        }
      }
    }
    if (fix < 128) {
      EXPECT_TRUE(stoppedShort) << "fix " << fix << ": floor should leave some texels below the target";
    }
  }
  EXPECT_EQ(stallBand(64), 1);
  EXPECT_EQ(stallBand(128), 0);
  EXPECT_EQ(stallBand(32), 3);
  EXPECT_EQ(stallBand(1), 127);
}

TEST(Blend, FixOutsideRangeIsRefused) {
  EXPECT_NO_THROW(makeBlendSpec(0));
  EXPECT_NO_THROW(makeBlendSpec(255));
  for (std::int64_t bad : {-1LL, 256LL, 1000LL}) {
    try {
      makeBlendSpec(bad);
      FAIL() << "FIX " << bad << " accepted";
    } catch (const GsError& e) {
      EXPECT_NE(std::string(e.what()).find("outside 0..255"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(std::to_string(bad)), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace vbim::gs
