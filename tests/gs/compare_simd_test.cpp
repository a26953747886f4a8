// The per-byte difference (gs/image_compare.hpp): the scalar reference against a plain
// definition, then every compiled SIMD target against the scalar reference: every byte pair, random
// rectangles of every width from 1 to 300 bytes (the scalar tails), strides, extremes (the sum of
// a large image of 255s), and whole images through compareImages.
#include "gs/simd/compare_simd.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <vector>

#include "gs/error.hpp"
#include "gs/lag_meter.hpp"
#include "gs/simd/blend_simd.hpp"
#include "runtime/rng.hpp"

namespace vbim::gs {
namespace {

ByteDifference plainDefinition(const std::vector<std::uint8_t>& a, std::size_t aOff, std::size_t aStride,
                               const std::vector<std::uint8_t>& b, std::size_t bOff, std::size_t bStride,
                               std::size_t bytes, std::size_t rows) {
  ByteDifference d;
  for (std::size_t y = 0; y < rows; ++y) {
    for (std::size_t i = 0; i < bytes; ++i) {
      const int v = std::abs(a[aOff + y * aStride + i] - b[bOff + y * bStride + i]);
      d.max = std::max(d.max, v);
      d.sum += v;
    }
  }
  return d;
}

std::vector<std::uint8_t> randomBytes(Rng& rng, std::size_t n, int spread) {
  std::vector<std::uint8_t> v(n);
  for (auto& x : v) x = static_cast<std::uint8_t>(rng.below(static_cast<std::uint64_t>(spread)));
  return v;
}

TEST(CompareSimd, ScalarMatchesThePlainDefinition) {
  Rng rng(3);
  for (int k = 0; k < 200; ++k) {
    const std::size_t bytes = 1 + rng.below(300), rows = 1 + rng.below(6);
    const std::size_t aStride = bytes + rng.below(40), bStride = bytes + rng.below(40);
    const auto a = randomBytes(rng, aStride * rows + 8, 256);
    const auto b = randomBytes(rng, bStride * rows + 8, 256);
    const ByteDifference want = plainDefinition(a, 3, aStride, b, 5, bStride, bytes, rows);
    const ByteDifference got = compareRectScalar(a.data() + 3, aStride, b.data() + 5, bStride, bytes, rows);
    ASSERT_EQ(got.max, want.max);
    ASSERT_EQ(got.sum, want.sum);
  }
}

void expectSame(const ByteDifference& got, const ByteDifference& want, const std::string& what) {
  ASSERT_EQ(got.max, want.max) << what;
  ASSERT_EQ(got.sum, want.sum) << what;
}

TEST(CompareSimd, EveryTargetMatchesScalar) {
  std::set<std::string> targets;
  simd::forEachTarget([&](const std::string& target) {
    targets.insert(target);
    // Every (a, b) byte pair once, as one row and as 256 rows of 256.
    std::vector<std::uint8_t> a(65536), b(65536);
    for (int i = 0; i < 65536; ++i)
      a[i] = static_cast<std::uint8_t>(i & 0xFF), b[i] = static_cast<std::uint8_t>(i >> 8);
    expectSame(simd::compareRect(a.data(), 0, b.data(), 0, a.size(), 1),
               compareRectScalar(a.data(), 0, b.data(), 0, a.size(), 1), target + " all pairs");
    expectSame(simd::compareRect(a.data(), 256, b.data(), 256, 256, 256),
               compareRectScalar(a.data(), 256, b.data(), 256, 256, 256), target + " all pairs 256x256");
    // Random rectangles: odd widths (tails), offsets, strides, small and large differences; and a
    // single byte of difference anywhere.
    Rng rng(11);
    for (int k = 0; k < 600; ++k) {
      const std::size_t bytes = 1 + rng.below(300), rows = 1 + rng.below(5);
      const std::size_t aStride = bytes + rng.below(70), bStride = bytes + rng.below(70);
      const int spread = rng.chance(1, 2) ? 256 : 3;
      auto x = randomBytes(rng, aStride * rows + 64, spread);
      auto y = randomBytes(rng, bStride * rows + 64, spread);
      const std::size_t ax = rng.below(64), by = rng.below(64);
      if (rng.chance(1, 3)) {  // equal rectangles but for one byte
        for (std::size_t r = 0; r < rows; ++r)
          for (std::size_t i = 0; i < bytes; ++i) y[by + r * bStride + i] = x[ax + r * aStride + i];
        const std::size_t r = rng.below(rows), i = rng.below(bytes);
        y[by + r * bStride + i] = static_cast<std::uint8_t>(x[ax + r * aStride + i] ^ (1u << rng.below(8)));
      }
      expectSame(
          simd::compareRect(x.data() + ax, aStride, y.data() + by, bStride, bytes, rows),
          compareRectScalar(x.data() + ax, aStride, y.data() + by, bStride, bytes, rows),
          target + " case " + std::to_string(k) + ": " + std::to_string(bytes) + " bytes x " + std::to_string(rows));
    }
    // The largest difference everywhere: a 1024x1024 image of 0s against 255s (sum 255 * 4 Mi).
    std::vector<std::uint8_t> zeros(std::size_t{1024} * 1024 * 4, 0), full(zeros.size(), 255);
    const ByteDifference big = simd::compareRect(zeros.data(), 0, full.data(), 0, zeros.size(), 1);
    EXPECT_EQ(big.max, 255) << target;
    EXPECT_EQ(big.sum, std::int64_t{255} * static_cast<std::int64_t>(zeros.size())) << target;
    const ByteDifference none = simd::compareRect(full.data(), 0, full.data(), 0, full.size(), 1);
    EXPECT_EQ(none.max, 0) << target;
    EXPECT_EQ(none.sum, 0) << target;
  });
  EXPECT_FALSE(targets.empty());
}

TEST(CompareSimd, CompareImagesIsTheSameWithEitherKernels) {
  Rng rng(5);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{256, 256}, {128, 64}, {33, 7}, {1, 1}}) {
    Rgba8Image a(w, h), b(w, h);
    for (auto& x : a.pixels) x = static_cast<std::uint8_t>(rng.below(256));
    for (auto& x : b.pixels) x = static_cast<std::uint8_t>(rng.below(256));
    const LagSample s = compareImages(a, b);
    const LagSample v = compareImages(a, b, simd::kernels());
    EXPECT_EQ(s.maxDiff, v.maxDiff);
    EXPECT_EQ(s.sumDiff, v.sumDiff);
  }
  EXPECT_THROW(compareImages(Rgba8Image(4, 4), Rgba8Image(4, 5)), GsError);
}

}  // namespace
}  // namespace vbim::gs
