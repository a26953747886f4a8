// Shadows at every sun azimuth against an exact per-texel ray (issue #20).
//
// The reference: from each texel centre, the ray along the sun's exact azimuth, sampled at every
// integer step along the major axis (the grid axis closer to the azimuth), its height linearly
// interpolated between the two texels across the minor axis, at its exact distance; the horizon is
// the steepest of those samples. A texel is in shadow when that horizon is above the sun's centre.
// Compared on synthetic walls and cones, a real DEM excerpt (tests/lighting/data/README.md) and the
// procedural terrain, at azimuths in 5 degree steps and elevations 3..60 degrees. The sheared-line
// sweep (lighting/azimuth_sweep.hpp) is measured alongside: it over-shadows at oblique azimuths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "lighting/azimuth_sweep.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/dem_reader.hpp"
#include "lighting/procedural_terrain.hpp"
#include "lighting/ray_sweep.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Tangent of the horizon along the exact ray from texel (x, y), clamped at 0.
double exactRayTan(const Terrain& t, double azimuth, int x, int y) {
  const double cx = std::cos(azimuth), cy = std::sin(azimuth);
  const bool majorIsCol = std::fabs(cx) >= std::fabs(cy);
  const double major = majorIsCol ? cx : cy, minor = majorIsCol ? cy : cx;
  const int du = major > 0 ? 1 : -1;
  const double dv = minor / std::fabs(major);  // minor cells per major step
  const int uSize = majorIsCol ? t.width : t.height, vSize = majorIsCol ? t.height : t.width;
  const int u0 = majorIsCol ? x : y, v0 = majorIsCol ? y : x;
  const double step = t.cellSize * std::sqrt(1 + dv * dv);
  const double h0 = t.metresAt(x, y);
  auto heightAt = [&](int u, int v) { return majorIsCol ? t.metresAt(u, v) : t.metresAt(v, u); };
  double best = 0;
  for (int k = 1;; ++k) {
    const int u = u0 + k * du;
    const double v = v0 + k * dv;
    if (u < 0 || u >= uSize || v < 0 || v > vSize - 1) break;
    const int a = std::min(static_cast<int>(std::floor(v)), vSize - 1), b = std::min(a + 1, vSize - 1);
    const double f = v - a;
    const double h = heightAt(u, a) + (heightAt(u, b) - heightAt(u, a)) * f;
    best = std::max(best, (h - h0) / (k * step));
  }
  return best;
}

struct Mismatch {
  long cells = 0;     // cells whose shadow differs from the exact ray's
  long boundary = 0;  // cells at the exact mask's terminator (one of the 8 neighbours in the other state)
};

Mismatch compare(const Terrain& t, const std::vector<double>& exact, const std::vector<float>& fast, double elev) {
  const double tanSun = std::tan(elev);
  auto shadowExact = [&](int x, int y) { return exact[static_cast<std::size_t>(y) * t.width + x] > tanSun; };
  Mismatch m;
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * t.width + x;
      const bool s = shadowExact(x, y);
      if (s != (fast[i] > tanSun)) ++m.cells;
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && xx < t.width && yy >= 0 && yy < t.height && shadowExact(xx, yy) != s) edge = true;
        }
      }
      if (edge) ++m.boundary;
    }
  }
  return m;
}

// Soft visibility of a sun disc of 1.5 degrees (the article's linear ramp, lighting/day_cycle.hpp)
// and its total variation over the grid: jagged penumbrae add variation, smooth ones do not.
double totalVariation(const Terrain& t, const std::vector<float>& tangents, double elev) {
  auto vis = [&](int x, int y) {
    return sunOcclusion(std::atan(tangents[static_cast<std::size_t>(y) * t.width + x]), elev, 1.5 * kDeg, false);
  };
  double tv = 0;
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      if (x + 1 < t.width) tv += std::fabs(vis(x + 1, y) - vis(x, y));
      if (y + 1 < t.height) tv += std::fabs(vis(x, y + 1) - vis(x, y));
    }
  }
  return tv;
}

struct Totals {
  long sheared = 0, rays = 0, boundary = 0;
  double tvExact = 0, tvSheared = 0, tvRays = 0;  // total variation of the soft visibility
  double worstRatio = 0;                          // rays mismatches / terminator cells, worst single sun position
  std::string worstAt;
};

using Sweep = void (*)(const Terrain&, double, float*, WorkerPool*);

Totals sweepAll(const Terrain& t, const std::string& name) {
  Totals tot;
  std::vector<double> exact(t.texels());
  std::vector<float> sheared(t.texels()), rays(t.texels());
  for (int a = 0; a < 360; a += 5) {
    const double az = a * kDeg;
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x) exact[static_cast<std::size_t>(y) * t.width + x] = exactRayTan(t, az, x, y);
    sweepAzimuth(t, az, sheared.data());
    sweepRays(t, az, rays.data());
    for (int e : {3, 5, 10, 20, 30, 45, 60}) {
      const Mismatch ms = compare(t, exact, sheared, e * kDeg), mr = compare(t, exact, rays, e * kDeg);
      tot.sheared += ms.cells;
      tot.rays += mr.cells;
      tot.boundary += mr.boundary;
      std::vector<float> exactF(exact.begin(), exact.end());
      tot.tvExact += totalVariation(t, exactF, e * kDeg);
      tot.tvSheared += totalVariation(t, sheared, e * kDeg);
      tot.tvRays += totalVariation(t, rays, e * kDeg);
      if (mr.boundary >= 20) {
        const double ratio = static_cast<double>(mr.cells) / mr.boundary;
        if (ratio > tot.worstRatio) {
          tot.worstRatio = ratio;
          tot.worstAt = "azimuth " + std::to_string(a) + ", elevation " + std::to_string(e) + " (" +
                        std::to_string(mr.cells) + " of " + std::to_string(mr.boundary) + ")";
        }
      }
    }
  }
  std::printf(
      "%s: terminator cells %ld, differ from the exact ray: sheared lines %ld, rays %ld; worst %.3f at %s\n"
      "  penumbra total variation: exact %.0f, sheared lines %.0f, rays %.0f\n",
      name.c_str(), tot.boundary, tot.sheared, tot.rays, tot.worstRatio, tot.worstAt.c_str(), tot.tvExact,
      tot.tvSheared, tot.tvRays);
  // The bound (issue #20): r.sunmask differs from per-texel rays in about 15% of the cells near the
  // terminator at oblique suns; the ray sweep must do no worse at any sun position, and far better
  // over all of them than the sheared lines did. Its soft penumbra must be as smooth as the exact
  // ray's (total variation within 5%).
  EXPECT_LE(tot.worstRatio, 0.15) << name << ": worst at " << tot.worstAt;
  EXPECT_LE(tot.rays, tot.boundary * 3 / 100) << name;
  EXPECT_LE(tot.rays * 5, tot.sheared) << name;
  EXPECT_NEAR(tot.tvRays, tot.tvExact, 0.05 * tot.tvExact) << name;
  return tot;
}

Terrain fromMetres(int w, int h, double cell, const std::function<double(int, int)>& z) {
  std::vector<float> m(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m[static_cast<std::size_t>(y) * w + x] = static_cast<float>(z(x, y));
  return terrainFromMetres(w, h, m, cell, "synthetic");
}

TEST(ShadowRays, Walls) {
  // A one-cell wall 40 m high along a line at 30 degrees, and one along the grid, on flat ground.
  const Terrain t = fromMetres(96, 96, 10.0, [](int x, int y) {
    const double d = std::fabs((x - 48) * std::sin(30 * kDeg) - (y - 48) * std::cos(30 * kDeg));
    return (d < 0.5 && std::abs(x - 48) < 30) || (x == 20 && y > 10 && y < 40) ? 40.0 : 0.0;
  });
  sweepAll(t, "walls");
}

TEST(ShadowRays, Cones) {
  const Terrain t = fromMetres(96, 96, 10.0, [](int x, int y) {
    double h = 0;
    // Flanks of 47, 34 and 53 degrees: none exactly at a tested sun elevation, where every texel of
    // a flank would graze the sun and its shadow would be decided by rounding alone.
    for (const auto& [cx, cy, r, top] :
         {std::tuple{30.0, 30.0, 12.0, 130.0}, {65.3, 40.7, 9.0, 60.0}, {45.0, 70.0, 15.0, 200.0}}) {
      h = std::max(h, top * (1 - std::hypot(x - cx, y - cy) / r));
    }
    return h;
  });
  sweepAll(t, "cones");
}

TEST(ShadowRays, RealDem) {
  const Dem dem =
      readDem((std::filesystem::path(VBIM_SOURCE_DIR) / "tests/lighting/data/luxembourg_elev.tif").string());
  sweepAll(dem.terrain, "luxembourg");
}

TEST(ShadowRays, ProceduralMountains) {
  const Terrain t = proceduralTerrain({.size = 96, .cellSize = 20.0, .reliefMetres = 900.0, .seed = 3});
  sweepAll(t, "procedural");
}

}  // namespace
}  // namespace vbim::lighting
