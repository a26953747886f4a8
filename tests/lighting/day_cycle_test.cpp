// Items 1, 3 and 5: per-frame relight, the frame API, the procedural terrain, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "config/params_toml.hpp"
#include "lighting/azimuth_sweep.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/error.hpp"
#include "lighting/procedural_terrain.hpp"
#include "runtime/param_table.hpp"
#include "runtime/worker_pool.hpp"
#include "tests/lighting/test_terrains.hpp"

namespace vbim::lighting {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

FrameLighting sunOnly(double elevationDeg, double azimuthDeg) {
  FrameLighting f;
  f.key.elevation = elevationDeg * kDeg;
  f.key.azimuth = azimuthDeg * kDeg;
  f.key.direction = {std::cos(f.key.elevation) * std::cos(f.key.azimuth),
                     std::cos(f.key.elevation) * std::sin(f.key.azimuth), std::sin(f.key.elevation)};
  f.sun = f.key;
  f.keyIrradiance = {1, 1, 1};
  return f;  // all sky patches zero
}

FloatImage relightWith(const Precomputed& pre, const FrameLighting& f, const DayCycleParams& p,
                       FloatImage* mask = nullptr) {
  std::vector<float> horizon(pre.terrain.texels());
  sweepAzimuth(pre.terrain, f.key.azimuth, horizon.data());
  FloatImage out;
  relight(pre, f, horizon.data(), CloudLayer(p.clouds), p, out, mask);
  return out;
}

TEST(Relight, FlatTerrainIrradianceIsProportionalToSinElevation) {
  const Precomputed pre = precompute(testing::flatTerrain(32, 32), 1);
  const DayCycleParams p;
  for (double e : {5.0, 10.0, 30.0, 60.0, 89.0}) {
    const FloatImage out = relightWith(pre, sunOnly(e, 37.0), p);
    for (std::size_t i = 0; i < pre.terrain.texels(); ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(out.pixels[i * 3 + c], std::sin(e * kDeg), 1e-6) << e;
    }
  }
}

TEST(Relight, SunBehindAWallIsShadowedThenLit) {
  // A 100 m wall on the eastern edge; texel 10 cells (100 m) west of it. Horizon towards the east
  // is 45 deg: a sun at 30 deg is hidden, at 60 deg it is not, at 45 deg the disc is half hidden.
  const int w = 21, h = 5;
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) counts[static_cast<std::size_t>(y) * w + 20] = 100;
  const Precomputed pre = precompute(terrainFromCounts(w, h, counts, 10.0, 1.0, "wall"), 1);
  DayCycleParams p;
  p.sunDiameterDeg = 2.0;
  const std::size_t i = 2 * w + 10;
  FloatImage mask;
  relightWith(pre, sunOnly(30, 0), p, &mask);
  EXPECT_EQ(mask.pixels[i], 0.0f);
  relightWith(pre, sunOnly(60, 0), p, &mask);
  EXPECT_EQ(mask.pixels[i], 1.0f);
  relightWith(pre, sunOnly(45, 0), p, &mask);
  EXPECT_NEAR(mask.pixels[i], 0.5f, 0.01f);
  relightWith(pre, sunOnly(30, 180), p, &mask);  // the same sun in the west: open
  EXPECT_EQ(mask.pixels[i], 1.0f);
}

TEST(Relight, SkyOnlyLightingIsPatchRadianceTimesSkyFactor) {
  const Precomputed pre = precompute(testing::randomTerrain(20, 20, 11, 4000), 2);
  DayCycleParams p;
  FrameLighting f = sunOnly(30, 0);
  f.keyIrradiance = {0, 0, 0};
  f.patch[0] = {0.2f, 0.3f, 0.4f};
  f.patch[1] = {0.1f, 0.1f, 0.1f};
  const FloatImage out = relightWith(pre, f, p);
  for (std::size_t i = 0; i < pre.terrain.texels(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float want =
          f.patch[0][c] * pre.sky.factor[(i * 2) * 3 + c] + f.patch[1][c] * pre.sky.factor[(i * 2 + 1) * 3 + c];
      EXPECT_NEAR(out.pixels[i * 3 + c], want, 1e-6);
    }
  }
}

TEST(NormalPalette, FitsTheTerrain) {
  const Terrain t = proceduralTerrain({.size = 128, .cellSize = 20.0, .reliefMetres = 900.0, .seed = 3});
  const std::vector<Vec3> normals = terrainNormals(t);
  auto meanError = [&](const NormalPalette& pal) {
    double sum = 0;
    for (std::size_t i = 0; i < normals.size(); ++i) {
      const Vec3& a = normals[i];
      const Vec3& b = pal.normals[pal.index[i]];
      sum += std::acos(std::min(1.0, static_cast<double>(a.x * b.x + a.y * b.y + a.z * b.z)));
    }
    return sum / normals.size();
  };
  const NormalPalette pal = buildNormalPalette(normals);
  const double fitted = meanError(pal), cap = meanError(buildNormalPalette(normals, 0));
  // A uniform hemisphere palette averages 3.5 deg (docs/lighting.md#normal-palette); k-means on the
  // terrain does better.
  EXPECT_LT(fitted, 0.8 * cap) << fitted / kDeg << " vs " << cap / kDeg;
  EXPECT_LT(fitted, 3.0 * kDeg);
  EXPECT_LT(maxPaletteError(pal, normals), 12.0 * kDeg);
  // A flat terrain's palette holds the exact up vector.
  const std::vector<Vec3> flat = terrainNormals(testing::flatTerrain(8, 8));
  EXPECT_EQ(maxPaletteError(buildNormalPalette(flat), flat), 0.0);
}

TEST(ProceduralTerrain, IsDeterministicAndHasRelief) {
  const ProceduralTerrainParams p{.size = 64, .cellSize = 10.0, .reliefMetres = 500.0, .seed = 5};
  const Terrain a = proceduralTerrain(p), b = proceduralTerrain(p);
  EXPECT_EQ(a.heights, b.heights);
  const auto [lo, hi] = std::minmax_element(a.heights.begin(), a.heights.end());
  EXPECT_NEAR((*hi - *lo) * a.heightStep, 500.0, 100.0);
  EXPECT_NE(proceduralTerrain({.size = 64, .cellSize = 10.0, .reliefMetres = 500.0, .seed = 6}).heights, a.heights);
}

DayCycleParams smallCycle() {
  DayCycleParams p;
  p.frames = 6;
  p.startHour = 0;
  p.endHour = 24;
  p.skyWidth = 32;
  p.clouds.enabled = true;
  return p;
}

TEST(DayCycle, FramesAreDeterministicAndIndependentOfThreads) {
  const Terrain t = proceduralTerrain({.size = 48, .cellSize = 20.0, .reliefMetres = 600.0, .seed = 2});
  WorkerPool pool(2);
  DayCycleGenerator serial(t, smallCycle()), parallel(t, smallCycle(), &pool);
  ASSERT_EQ(serial.frameCount(), 6);
  for (int i : {3, 1, 5, 0}) {
    Rgba8Image a, sa, b, sb;
    serial.renderFrame(i, a, sa);
    parallel.renderFrame(i, b, sb);
    EXPECT_EQ(a.pixels, b.pixels) << i;
    EXPECT_EQ(sa.pixels, sb.pixels) << i;
    EXPECT_EQ(a.width, 48);
    EXPECT_EQ(sa.width, 32);
    EXPECT_EQ(sa.height, 16);
    EXPECT_EQ(a.pixels[3], 0x80);
  }
}

TEST(DayCycle, NoonIsBrightMidnightIsDimAndMoonlit) {
  const Terrain t = testing::flatTerrain(16, 16);
  DayCycleGenerator g(t, smallCycle());  // frames at 0, 4, 8, 12, 16, 20 h
  EXPECT_DOUBLE_EQ(g.frameHour(3), 12.0);
  FloatImage noon, night, sky;
  g.renderFrame(3, noon, sky);
  g.renderFrame(0, night, sky);
  EXPECT_GT(noon.pixels[0], 0.6f);
  EXPECT_LT(night.pixels[0], 0.1f);
  EXPECT_GT(night.pixels[2], night.pixels[0]);  // bluish night
  EXPECT_TRUE(g.frameLighting(0).keyIsMoon);
  EXPECT_FALSE(g.frameLighting(3).keyIsMoon);
  // Noon on flat ground: sun on the horizontal plus pi L_sky, normalised by the exposure.
  const FrameLighting f = g.frameLighting(3);
  const double expected = f.keyIrradiance[1] * std::sin(f.key.elevation) + f.patch[0][1] + 0 * f.patch[1][1];
  EXPECT_GT(noon.pixels[1], 0.9 * expected);
}

TEST(DayCycle, MultiplyAlbedoScalesByTheColourMap) {
  Terrain t = testing::flatTerrain(8, 8);
  FloatImage albedo(8, 8, 3);
  for (std::size_t i = 0; i < albedo.pixels.size(); ++i) albedo.pixels[i] = (i % 3 == 0) ? 0.5f : 0.25f;
  setAlbedo(t, albedo, "albedo");
  DayCycleParams p = smallCycle();
  p.clouds.enabled = false;
  DayCycleGenerator plain(t, p);
  p.multiplyAlbedo = true;
  DayCycleGenerator coloured(t, p);
  FloatImage a, b, sky;
  plain.renderFrame(3, a, sky);
  coloured.renderFrame(3, b, sky);
  EXPECT_NEAR(b.pixels[0], a.pixels[0] * 0.5f, 1e-6);
  EXPECT_NEAR(b.pixels[1], a.pixels[1] * 0.25f, 1e-6);
}

TEST(BadInput, ParametersOutOfRangeAreRejectedByKey) {
  auto message = [](DayCycleParams p) {
    try {
      validateParams(p);
    } catch (const LightingError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  DayCycleParams p;
  EXPECT_EQ(message(p), "");
  p.latitudeDeg = 95;
  EXPECT_NE(message(p).find("lighting.latitude_deg = 95 is outside [-90, 90]"), std::string::npos) << message(p);
  p = {};
  p.latitudeDeg = -90.5;
  EXPECT_NE(message(p).find("latitude"), std::string::npos);
  p = {};
  p.frames = 0;
  EXPECT_NE(message(p).find("lighting.frames = 0"), std::string::npos);
  p = {};
  p.skyPatches = 9;
  EXPECT_NE(message(p).find("sky_patches"), std::string::npos);
  p = {};
  p.startHour = 10;
  p.endHour = 8;
  EXPECT_NE(message(p).find("before"), std::string::npos);
  p = {};
  p.latitudeDeg = std::nan("");
  EXPECT_NE(message(p).find("latitude"), std::string::npos);
  EXPECT_THROW(DayCycleGenerator(testing::flatTerrain(4, 4),
                                 [] {
                                   DayCycleParams q;
                                   q.frames = 0;
                                   return q;
                                 }()),
               LightingError);
}

TEST(BadInput, HeightfieldsAndColourMaps) {
  EXPECT_THROW(terrainFromMetres(0, 0, {}, 10.0, "empty.exr"), LightingError);
  std::vector<float> m(6, 1.0f);
  m[4] = std::nanf("");
  try {
    terrainFromMetres(3, 2, m, 10.0, "hf.exr");
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("hf.exr: height at pixel (1, 1) is NaN"), std::string::npos) << e.what();
  }
  m[4] = INFINITY;
  EXPECT_THROW(terrainFromMetres(3, 2, m, 10.0, "hf.exr"), LightingError);
  Terrain t = testing::flatTerrain(8, 8);
  try {
    setAlbedo(t, FloatImage(8, 7, 3), "colour.png");
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("colour.png: colour map is 8x7, expected the heightfield's size 8x8"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(setAlbedo(t, FloatImage(8, 8, 1), "grey.png"), LightingError);
  DayCycleGenerator g(testing::flatTerrain(4, 4), smallCycle());
  FloatImage a, b;
  EXPECT_THROW(g.renderFrame(6, a, b), LightingError);
  EXPECT_THROW(g.renderFrame(-1, a, b), LightingError);
}

TEST(Params, DescribeParamsLoadsToml) {
  DayCycleParams p;
  ParamTable table;
  describeParams(table, p);
  config::applyToml(table, "[lighting]\nlatitude_deg = -33.9\nframes = 48\n[lighting.clouds]\nenabled = true\n",
                    "<test>");
  EXPECT_DOUBLE_EQ(p.latitudeDeg, -33.9);
  EXPECT_EQ(p.frames, 48);
  EXPECT_TRUE(p.clouds.enabled);
  EXPECT_THROW(config::applyToml(table, "[lighting]\nlatitude_deg = 120\n", "<test>"), ConfigError);
}

}  // namespace
}  // namespace vbim::lighting
