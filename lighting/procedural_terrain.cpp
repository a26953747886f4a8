#include "lighting/procedural_terrain.hpp"

#include <algorithm>
#include <cmath>

#include "lighting/error.hpp"

namespace vbim::lighting {

namespace {

// SplitMix64 finaliser of the lattice coordinates: a well-mixed, platform-independent hash.
double lattice(std::int64_t ix, std::int64_t iy, std::uint64_t salt) {
  std::uint64_t z = static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ULL ^
                    static_cast<std::uint64_t>(iy) * 0xC2B2AE3D27D4EB4FULL ^ salt;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);  // [0, 1)
}

double fade(double t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

// Value noise with period `period` lattice cells (tiles seamlessly), in [0, 1).
double valueNoise(double x, double y, std::int64_t period, std::uint64_t salt) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double tx = fade(x - fx), ty = fade(y - fy);
  auto w = [period](std::int64_t v) { return ((v % period) + period) % period; };
  const double a = lattice(w(ix), w(iy), salt), b = lattice(w(ix + 1), w(iy), salt);
  const double c = lattice(w(ix), w(iy + 1), salt), d = lattice(w(ix + 1), w(iy + 1), salt);
  return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
}

}  // namespace

Terrain proceduralTerrain(const ProceduralTerrainParams& p) {
  if (p.size < 2 || p.size > 16384) throw LightingError("procedural terrain: size must be 2..16384 texels");
  if (!(p.cellSize > 0)) throw LightingError("procedural terrain: cell size must be positive");
  if (!(p.reliefMetres > 0) || p.reliefMetres > 20000) {
    throw LightingError("procedural terrain: relief must be in (0, 20000] metres");
  }
  const int n = static_cast<int>(p.size);
  std::vector<float> metres(static_cast<std::size_t>(n) * n);
  const auto seed = static_cast<std::uint64_t>(p.seed) * 0xD1B54A32D192ED03ULL;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double u = static_cast<double>(x) / n, v = static_cast<double>(y) / n;
      // Ridged multifractal for the mountains, plain fBm for the hills; both tile with the map.
      double ridged = 0, hills = 0, amp = 0.5, norm = 0;
      std::int64_t period = 4;
      for (int octave = 0; octave < 8; ++octave) {
        const double r = valueNoise(u * period, v * period, period, seed + static_cast<std::uint64_t>(octave) * 7919u);
        const double ridge = 1.0 - std::fabs(2.0 * r - 1.0);
        ridged += amp * ridge * ridge;
        hills += amp * valueNoise(u * period + 17.3, v * period + 5.1, period, seed + 104729u + octave);
        norm += amp;
        amp *= 0.5;
        period *= 2;
      }
      ridged /= norm;
      hills /= norm;
      // Mountains rise towards the map's north-west; a valley floor at 18 % stays flat.
      const double mask = std::clamp(1.3 - 0.9 * (u + v), 0.15, 1.0);
      double h = 0.75 * ridged * ridged * mask * 1.8 + 0.25 * hills;
      h = std::max(h, 0.18);
      metres[static_cast<std::size_t>(y) * n + x] = static_cast<float>((h - 0.18) / 0.82 * p.reliefMetres);
    }
  }
  return terrainFromMetres(n, n, metres, p.cellSize, "procedural terrain");
}

FloatImage proceduralAlbedo(const Terrain& t) {
  const std::vector<Vec3> normals = terrainNormals(t);
  double top = 1e-9;
  for (auto h : t.heights) top = std::max(top, static_cast<double>(h));
  FloatImage img(t.width, t.height, 3);
  const float grass[3] = {0.10f, 0.16f, 0.05f}, rock[3] = {0.26f, 0.23f, 0.20f}, snow[3] = {0.80f, 0.82f, 0.85f};
  for (std::size_t i = 0; i < t.texels(); ++i) {
    const double rel = t.heights[i] / top;
    const double steep = std::clamp((0.93 - normals[i].z) / 0.12, 0.0, 1.0);  // rock above ~25 deg
    const double snowy = std::clamp((rel - 0.72) / 0.1, 0.0, 1.0) * (1 - 0.7 * steep);
    for (int c = 0; c < 3; ++c) {
      const double base = grass[c] + (rock[c] - grass[c]) * steep;
      img.pixels[i * 3 + c] = static_cast<float>(base + (snow[c] - base) * snowy);
    }
  }
  return img;
}

}  // namespace vbim::lighting
