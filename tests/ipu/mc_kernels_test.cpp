// Motion compensation's Highway kernels (ipu/simd/mc_kernels.hpp) against the scalar reference
// (ipu/mc_kernels.hpp): every width, half-sample case and averaging mode, on random blocks at random
// positions with frame and field strides.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <random>
#include <vector>

#include "ipu/mc_kernels.hpp"
#include "ipu/simd/mc_kernels.hpp"

namespace vbim::ipu {
namespace {

// Runs f(kernels) once per instruction set this binary has code for and the machine runs.
template <class F>
void forEachTarget(F&& f) {
  for (std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    const McKernels k = simdMcKernelsOfCurrentTarget();
    f(k);
  }
  hwy::SetSupportedTargetsForTest(0);
}

TEST(IpuMcKernels, PredictMatchesScalar) {
  forEachTarget([](const McKernels& simd) {
    const McKernels& ref = scalarMcKernels();
    std::mt19937 rng(29);
    constexpr int kStride = 96;
    constexpr int kLines = 64;
    std::vector<std::uint8_t> plane(static_cast<std::size_t>(kStride) * kLines);
    std::vector<std::uint8_t> want(plane.size());
    std::vector<std::uint8_t> got(plane.size());
    int cases = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // Smooth, noisy, or extreme (0 and 255 only: the rounding corners) samples.
      const int kind = trial % 3;
      for (std::size_t i = 0; i < plane.size(); ++i) {
        const auto r = rng();
        plane[i] = static_cast<std::uint8_t>(kind == 0 ? (i % kStride) * 2 + (r & 3) : (kind == 1 ? r : (r & 1) * 255));
      }
      for (std::size_t i = 0; i < want.size(); ++i) want[i] = got[i] = static_cast<std::uint8_t>(rng());
      for (int average = 0; average < 2; ++average) {
        for (int wide = 0; wide < 2; ++wide) {
          for (int hv = 0; hv < 4; ++hv) {
            for (const int field : {1, 2}) {
              const int width = wide ? 16 : 8;
              const int rows = (wide ? 16 : 8) >> (rng() % 2 + field - 1);  // 16/8 luma, 8/4 chroma, field halves
              const std::ptrdiff_t stride = std::ptrdiff_t{kStride} * field;
              const int linesAvailable = kLines / field;
              // Up to the last position the case may read from (one column right, one row below).
              const int x = static_cast<int>(rng() % static_cast<unsigned>(kStride - width - (hv & 1) + 1));
              const int y = static_cast<int>(rng() % static_cast<unsigned>(linesAvailable - rows - (hv >> 1) + 1));
              const std::uint8_t* src = plane.data() + (field - 1) * (rng() % 2) * kStride + y * stride + x;
              const int dx = static_cast<int>(rng() % static_cast<unsigned>(kStride - width + 1));
              const int dy = static_cast<int>(rng() % static_cast<unsigned>(linesAvailable - rows + 1));
              const std::ptrdiff_t dst = dy * stride + dx;
              ref.predict[average][wide][hv](want.data() + dst, stride, src, stride, rows);
              simd.predict[average][wide][hv](got.data() + dst, stride, src, stride, rows);
              ASSERT_EQ(want, got) << "average " << average << " width " << width << " case " << hv << " field stride "
                                   << field << " rows " << rows << " trial " << trial;
              ++cases;
            }
          }
        }
      }
    }
    EXPECT_EQ(cases, 400 * 2 * 2 * 4 * 2);
  });
}

// The four-sample case over every pair of sums it can see: a block whose rows hold all values of
// (a, b) and (c, d) through two rows per pair.
TEST(IpuMcKernels, FourSampleRoundingExhaustiveOverPairs) {
  forEachTarget([](const McKernels& simd) {
    const McKernels& ref = scalarMcKernels();
    // Row 0: a, b alternating pairs; row 1: c, d. Walk all (a, b) against a set of (c, d).
    std::vector<std::uint8_t> src(2 * 17);
    std::uint8_t want[16];
    std::uint8_t got[16];
    for (int ab = 0; ab < 65536; ab += 1) {
      for (int cd = 0; cd < 65536; cd += 509) {
        src[0] = static_cast<std::uint8_t>(ab >> 8);
        src[1] = static_cast<std::uint8_t>(ab);
        src[17] = static_cast<std::uint8_t>(cd >> 8);
        src[18] = static_cast<std::uint8_t>(cd);
        for (int k = 2; k < 17; ++k) {
          src[k] = src[k - 2];
          src[17 + k] = src[17 + k - 2];
        }
        ref.predict[0][1][3](want, 16, src.data(), 17, 1);
        simd.predict[0][1][3](got, 16, src.data(), 17, 1);
        for (int c = 0; c < 16; ++c) {
          const int a = src[c], b = src[c + 1], d = src[17 + c], e = src[18 + c];
          ASSERT_EQ(want[c], (a + b + d + e + 2) >> 2);
          ASSERT_EQ(got[c], want[c]) << a << " " << b << " " << d << " " << e;
        }
      }
    }
  });
}

}  // namespace
}  // namespace vbim::ipu
