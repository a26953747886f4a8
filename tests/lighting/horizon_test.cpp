// Item 2 and item 5 ("fast horizon scans equal brute force exactly").
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lighting/azimuth_sweep.hpp"
#include "lighting/fixed_angle.hpp"
#include "lighting/horizon_scan.hpp"
#include "lighting/ray_sweep.hpp"
#include "runtime/worker_pool.hpp"
#include "tests/lighting/test_terrains.hpp"

namespace vbim::lighting {
namespace {

using testing::flatTerrain;
using testing::randomTerrain;

TEST(FixedAngle, ArticleScaleZeroToNinetyDegrees) {
  EXPECT_EQ(codeFromAngle(0.0), 0);
  EXPECT_EQ(codeFromAngle(std::numbers::pi / 2), 0xFFFF);
  EXPECT_EQ(codeFromAngle(-0.3), 0);  // zero-elevation clamp
  EXPECT_EQ(codeFromTangent(-1.0), 0);
  EXPECT_EQ(codeFromTangent(1.0), codeFromAngle(std::numbers::pi / 4));
  for (double t : {1e-4, 0.01, 0.3, 0.99, 1.0, 1.7, 25.0, 1e4}) {
    const int exact = codeFromAngle(std::atan(t));
    EXPECT_LE(std::abs(codeFromTangent(t) - exact), 1) << t;
  }
}

TEST(HorizonScan, FastEqualsBruteForceExactlyInAllEightDirections) {
  struct Case {
    int w, h;
    std::uint32_t range;
  };
  const Case cases[] = {{1, 1, 10}, {1, 9, 50}, {9, 1, 50}, {37, 23, 4}, {23, 37, 4000}, {64, 64, 65535}, {50, 3, 2}};
  std::uint64_t seed = 1;
  for (const Case& c : cases) {
    const Terrain t = randomTerrain(c.w, c.h, seed++, c.range);
    for (int d = 0; d < kDirections; ++d) {
      std::vector<std::uint16_t> fast(t.texels(), 0xAAAA), brute(t.texels(), 0x5555);
      scanHorizon(t, d, fast.data());
      scanHorizonBruteForce(t, d, brute.data());
      EXPECT_EQ(fast, brute) << c.w << "x" << c.h << " direction " << kDirectionNames[d];
    }
  }
}

TEST(HorizonScan, ParallelResultEqualsSerial) {
  const Terrain t = randomTerrain(150, 97, 9, 3000);
  WorkerPool pool(2);
  const HorizonMaps a = computeHorizons(t), b = computeHorizons(t, &pool);
  for (int d = 0; d < kDirections; ++d) EXPECT_EQ(a.code[d], b.code[d]) << d;
}

TEST(HorizonScan, DirectionsFollowTheGridBasis) {
  // One tall post at (5, 5) on flat ground 10 m cells: seen from (2, 5) it is 3 cells east.
  std::vector<std::uint32_t> counts(11 * 11, 0);
  counts[5 * 11 + 5] = 30;  // 30 m at 1 m per count
  const Terrain t = terrainFromCounts(11, 11, counts, 10.0, 1.0, "post");
  const HorizonMaps m = computeHorizons(t);
  auto code = [&](int d, int x, int y) { return m.code[d][static_cast<std::size_t>(y) * 11 + x]; };
  auto near = [](int a, double radians) { return std::abs(a - codeFromAngle(radians)) <= 1; };
  EXPECT_TRUE(near(code(0, 2, 5), std::atan(30.0 / 30.0)));                     // E
  EXPECT_TRUE(near(code(2, 5, 3), std::atan(30.0 / 20.0)));                     // S (+row)
  EXPECT_TRUE(near(code(6, 5, 8), std::atan(30.0 / 30.0)));                     // N
  EXPECT_TRUE(near(code(1, 3, 3), std::atan(30.0 / (20.0 * std::sqrt(2.0)))));  // SE
  EXPECT_TRUE(near(code(5, 7, 7), std::atan(30.0 / (20.0 * std::sqrt(2.0)))));  // NW
  EXPECT_EQ(code(4, 2, 5), 0);  // looking west from west of the post: open
  EXPECT_EQ(code(0, 5, 5), 0);  // the post's own horizon
}

TEST(HorizonScan, DescendingTerrainClampsToZero) {
  std::vector<std::uint32_t> counts(20);
  for (int x = 0; x < 20; ++x) counts[x] = 100 - x;  // falls towards the east
  const Terrain t = terrainFromCounts(20, 1, counts, 1.0, 1.0, "ramp");
  std::vector<std::uint16_t> east(20);
  scanHorizon(t, 0, east.data());
  for (auto c : east) EXPECT_EQ(c, 0);
  std::vector<std::uint16_t> west(20);
  scanHorizon(t, 4, west.data());
  for (int x = 1; x < 20; ++x) EXPECT_EQ(west[x], codeFromAngle(std::numbers::pi / 4)) << x;
}

TEST(AzimuthSweep, FastEqualsBruteForceExactlyAtAnyAzimuth) {
  const Terrain t = randomTerrain(41, 29, 77, 500);
  for (double a : {0.0, 0.3, std::numbers::pi / 4, 1.2, std::numbers::pi / 2, 2.5, std::numbers::pi, -0.7, -2.9,
                   -std::numbers::pi / 2, 4.0}) {
    std::vector<float> fast(t.texels(), -1.0f), brute(t.texels(), -2.0f);
    sweepAzimuth(t, a, fast.data());
    sweepAzimuthBruteForce(t, a, brute.data());
    EXPECT_EQ(fast, brute) << "azimuth " << a;
  }
}

TEST(AzimuthSweep, ParallelEqualsSerialAndCoversEveryTexel) {
  const Terrain t = randomTerrain(90, 70, 5, 800);
  WorkerPool pool(2);
  std::vector<float> a(t.texels(), -1.0f), b(t.texels(), -1.0f);
  sweepAzimuth(t, 2.2, a.data());
  sweepAzimuth(t, 2.2, b.data(), &pool);
  EXPECT_EQ(a, b);
  for (float v : a) EXPECT_GE(v, 0.0f);  // every texel written, zero clamp
}

TEST(AzimuthSweep, AgreesWithTheGridScanAlongTheGrid) {
  const Terrain t = randomTerrain(33, 33, 3, 2000);
  for (int d : {0, 2, 4, 6}) {
    std::vector<std::uint16_t> grid(t.texels());
    scanHorizon(t, d, grid.data());
    std::vector<float> tangent(t.texels());
    sweepAzimuth(t, d * std::numbers::pi / 4, tangent.data());
    for (std::size_t i = 0; i < t.texels(); ++i) {
      EXPECT_LE(std::abs(codeFromTangent(tangent[i]) - grid[i]), 1) << "direction " << d << " texel " << i;
    }
  }
}

TEST(AzimuthSweep, FlatGroundHasAZeroHorizon) {
  const Terrain t = flatTerrain(16, 16);
  std::vector<float> tangent(t.texels(), 1.0f);
  sweepAzimuth(t, 0.9, tangent.data());
  for (float v : tangent) EXPECT_EQ(v, 0.0f);
}

TEST(RaySweep, FastEqualsBruteForceExactlyAtAnyAzimuth) {
  const Terrain t = randomTerrain(37, 26, 78, 500);
  for (double a : {0.0, 0.3, std::numbers::pi / 4, 1.2, std::numbers::pi / 2, 2.5, std::numbers::pi, -0.7, -2.9,
                   -std::numbers::pi / 2, 4.0, 0.01}) {
    std::vector<float> fast(t.texels(), -1.0f), brute(t.texels(), -2.0f);
    sweepRays(t, a, fast.data());
    sweepRaysBruteForce(t, a, brute.data());
    EXPECT_EQ(fast, brute) << "azimuth " << a;
  }
}

TEST(RaySweep, ParallelEqualsSerialAndCoversEveryTexel) {
  const Terrain t = randomTerrain(90, 70, 5, 800);
  WorkerPool pool(2);
  for (double a : {2.2, -0.4}) {
    std::vector<float> x(t.texels(), -1.0f), y(t.texels(), -1.0f);
    sweepRays(t, a, x.data());
    sweepRays(t, a, y.data(), &pool);
    EXPECT_EQ(x, y);
    for (float v : x) EXPECT_GE(v, 0.0f);  // every texel written, zero clamp
  }
}

// Along the grid axes every ray runs through texel centres: the same horizons as the exact grid scan.
// On the diagonals the distance is the exact sqrt(2) cells (the sheared sweep's fixed-point
// direction (2896, 2896) made it 1.1e-4 short).
TEST(RaySweep, AgreesWithTheGridScanAlongAxesAndDiagonals) {
  const Terrain t = randomTerrain(33, 33, 3, 2000);
  for (int d = 0; d < kDirections; ++d) {
    std::vector<std::uint16_t> grid(t.texels());
    scanHorizon(t, d, grid.data());
    std::vector<float> tangent(t.texels());
    sweepRays(t, d * std::numbers::pi / 4, tangent.data());
    for (std::size_t i = 0; i < t.texels(); ++i) {
      EXPECT_LE(std::abs(codeFromTangent(tangent[i]) - grid[i]), 1) << "direction " << d << " texel " << i;
    }
  }
}

TEST(RaySweep, FlatGroundHasAZeroHorizon) {
  const Terrain t = flatTerrain(16, 16);
  std::vector<float> tangent(t.texels(), 1.0f);
  sweepRays(t, 0.9, tangent.data());
  for (float v : tangent) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace vbim::lighting
