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
#include "runtime/simd/targets.hpp"

namespace vbim::ipu {
namespace {

// Runs f(kernels) once per instruction set this binary has code for and the machine runs.
template <class F>
void forEachTarget(F&& f) {
  vbim::simd::forEachTarget(HWY_TARGETS, [&](std::int64_t target) {
    SCOPED_TRACE(hwy::TargetName(target));
    const McKernels k = simdMcKernelsOfCurrentTarget();
    f(k);
  });
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

// The three-plane kernels (luma and both chroma blocks of one prediction in one call, Cb and Cr
// together in the Highway versions) against the scalar reference and against the per-plane
// kernels: every averaging mode and pair of luma and chroma half-sample cases, frame and field
// strides, full and half heights.
TEST(IpuMcKernels, BlockMatchesPlanes) {
  forEachTarget([](const McKernels& simd) {
    const McKernels& ref = scalarMcKernels();
    std::mt19937 rng(2929);
    constexpr int kStrideY = 96;
    constexpr int kStrideC = 48;
    constexpr int kLinesY = 64;
    constexpr int kLinesC = 32;
    auto randomPlane = [&](std::size_t n) {
      std::vector<std::uint8_t> p(n);
      for (auto& v : p) v = static_cast<std::uint8_t>(rng() % 3 == 0 ? (rng() & 1) * 255 : rng());
      return p;
    };
    int cases = 0;
    for (int trial = 0; trial < 100; ++trial) {
      const auto srcY = randomPlane(std::size_t{kStrideY} * kLinesY);
      const auto srcCb = randomPlane(std::size_t{kStrideC} * kLinesC);
      const auto srcCr = randomPlane(std::size_t{kStrideC} * kLinesC);
      const auto startY = randomPlane(srcY.size());
      const auto startCb = randomPlane(srcCb.size());
      const auto startCr = randomPlane(srcCr.size());
      for (int average = 0; average < 2; ++average) {
        for (int cy = 0; cy < 4; ++cy) {
          for (int cc = 0; cc < 4; ++cc) {
            for (const int field : {1, 2}) {
              const int rows = 16 >> (rng() % 2);  // 16 or 8 luma rows (field or 16x8 halves)
              const std::ptrdiff_t sy = std::ptrdiff_t{kStrideY} * field;
              const std::ptrdiff_t sc = std::ptrdiff_t{kStrideC} * field;
              const int linesY = kLinesY / field;
              const int linesC = kLinesC / field;
              const int xy = static_cast<int>(rng() % static_cast<unsigned>(kStrideY - 16 - (cy & 1) + 1));
              const int yy = static_cast<int>(rng() % static_cast<unsigned>(linesY - rows - (cy >> 1) + 1));
              const int xc = static_cast<int>(rng() % static_cast<unsigned>(kStrideC - 8 - (cc & 1) + 1));
              const int yc = static_cast<int>(rng() % static_cast<unsigned>(linesC - rows / 2 - (cc >> 1) + 1));
              const int dxy = static_cast<int>(rng() % (kStrideY - 16 + 1));
              const int dyy = static_cast<int>(rng() % static_cast<unsigned>(linesY - rows + 1));
              const int dxc = static_cast<int>(rng() % (kStrideC - 8 + 1));
              const int dyc = static_cast<int>(rng() % static_cast<unsigned>(linesC - rows / 2 + 1));
              const std::ptrdiff_t srcAtY = (field - 1) * (rng() % 2) * kStrideY + yy * sy + xy;
              const std::ptrdiff_t srcAtC = (field - 1) * (rng() % 2) * kStrideC + yc * sc + xc;
              // Expected: the scalar per-plane kernels.
              auto y0 = startY, cb0 = startCb, cr0 = startCr;
              ref.predict[average][1][cy](y0.data() + dyy * sy + dxy, sy, srcY.data() + srcAtY, sy, rows);
              ref.predict[average][0][cc](cb0.data() + dyc * sc + dxc, sc, srcCb.data() + srcAtC, sc, rows / 2);
              ref.predict[average][0][cc](cr0.data() + dyc * sc + dxc, sc, srcCr.data() + srcAtC, sc, rows / 2);
              for (const McKernels* k : {&ref, &simd}) {
                auto y1 = startY, cb1 = startCb, cr1 = startCr;
                const McBlock b{y1.data() + dyy * sy + dxy,
                                cb1.data() + dyc * sc + dxc,
                                cr1.data() + dyc * sc + dxc,
                                sy,
                                sc,
                                srcY.data() + srcAtY,
                                srcCb.data() + srcAtC,
                                srcCr.data() + srcAtC,
                                sy,
                                sc,
                                rows};
                k->block[average][cy][cc](b);
                ASSERT_EQ(y0, y1) << k->name << " average " << average << " cases " << cy << cc << " trial " << trial;
                ASSERT_EQ(cb0, cb1) << k->name << " average " << average << " cases " << cy << cc << " trial " << trial;
                ASSERT_EQ(cr0, cr1) << k->name << " average " << average << " cases " << cy << cc << " trial " << trial;
                ++cases;
              }
            }
          }
        }
      }
    }
    EXPECT_EQ(cases, 100 * 2 * 4 * 4 * 2 * 2);
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
