#include "lighting/terrain.hpp"

#include <algorithm>
#include <cmath>

#include "lighting/error.hpp"

namespace vbim::lighting {

namespace {

void checkGrid(int width, int height, std::size_t samples, double cellSize, const std::string& origin) {
  if (width <= 0 || height <= 0) {
    throw LightingError(origin + ": the heightfield is empty (" + std::to_string(width) + "x" + std::to_string(height) +
                        "); expected at least 1x1 samples");
  }
  if (samples != static_cast<std::size_t>(width) * height) {
    throw LightingError(origin + ": heightfield has " + std::to_string(samples) + " samples, expected " +
                        std::to_string(static_cast<std::size_t>(width) * height));
  }
  if (!(cellSize > 0) || !std::isfinite(cellSize)) {
    throw LightingError(origin + ": cell size must be a positive number of metres");
  }
}

}  // namespace

Terrain terrainFromMetres(int width, int height, const std::vector<float>& metres, double cellSize,
                          const std::string& origin) {
  checkGrid(width, height, metres.size(), cellSize, origin);
  double maxAbs = 0;
  for (std::size_t i = 0; i < metres.size(); ++i) {
    const float v = metres[i];
    if (!std::isfinite(v)) {
      throw LightingError(origin + ": height at pixel (" + std::to_string(i % width) + ", " +
                          std::to_string(i / width) + ") is " + (std::isnan(v) ? "NaN" : "infinite") +
                          "; expected a finite height");
    }
    maxAbs = std::max(maxAbs, static_cast<double>(std::fabs(v)));
  }
  Terrain t;
  t.width = width;
  t.height = height;
  t.cellSize = cellSize;
  t.heightStep = std::max(1.0 / 256.0, maxAbs / (kMaxHeightUnits / 2.0));
  t.heights.resize(metres.size());
  for (std::size_t i = 0; i < metres.size(); ++i) {
    t.heights[i] = static_cast<std::int32_t>(std::lround(metres[i] / t.heightStep));
  }
  return t;
}

Terrain terrainFromCounts(int width, int height, const std::vector<std::uint32_t>& counts, double cellSize,
                          double metresPerCount, const std::string& origin) {
  checkGrid(width, height, counts.size(), cellSize, origin);
  if (!(metresPerCount > 0) || !std::isfinite(metresPerCount)) {
    throw LightingError(origin + ": vertical scale must be a positive number of metres");
  }
  Terrain t;
  t.width = width;
  t.height = height;
  t.cellSize = cellSize;
  t.heightStep = metresPerCount;
  t.heights.resize(counts.size());
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] >= static_cast<std::uint32_t>(kMaxHeightUnits)) {
      throw LightingError(origin + ": sample at pixel (" + std::to_string(i % width) + ", " +
                          std::to_string(i / width) + ") exceeds 2^24 counts");
    }
    t.heights[i] = static_cast<std::int32_t>(counts[i]);
  }
  return t;
}

void setAlbedo(Terrain& terrain, FloatImage albedo, const std::string& origin) {
  if (albedo.width != terrain.width || albedo.height != terrain.height) {
    throw LightingError(origin + ": colour map is " + std::to_string(albedo.width) + "x" +
                        std::to_string(albedo.height) + ", expected the heightfield's size " +
                        std::to_string(terrain.width) + "x" + std::to_string(terrain.height));
  }
  if (albedo.channels != 3) {
    throw LightingError(origin + ": colour map has " + std::to_string(albedo.channels) + " channels, expected RGB (3)");
  }
  for (std::size_t i = 0; i < albedo.pixels.size(); ++i) {
    const float v = albedo.pixels[i];
    if (!std::isfinite(v) || v < 0) {
      const std::size_t p = i / 3;
      throw LightingError(origin + ": colour at pixel (" + std::to_string(p % albedo.width) + ", " +
                          std::to_string(p / albedo.width) + ") is not a finite non-negative value");
    }
    // A diffuse reflectance cannot exceed 1 (Hoffman & Mitchell, Game Developer 2001: "the color can
    // never be greater than 1.0").
    albedo.pixels[i] = std::min(v, 1.0f);
  }
  terrain.albedo = std::move(albedo);
}

void setBounceAlbedo(Terrain& terrain, FloatImage albedo, const std::string& origin) {
  Terrain check;  // the same checks and clamp, without touching the terrain's own albedo
  check.width = terrain.width;
  check.height = terrain.height;
  setAlbedo(check, std::move(albedo), origin);
  terrain.bounceAlbedo = std::move(check.albedo);
}

std::vector<Vec3> terrainNormals(const Terrain& t) {
  std::vector<Vec3> n(t.texels());
  const double k = t.heightStep / t.cellSize;
  for (int y = 0; y < t.height; ++y) {
    const int y0 = std::max(0, y - 1), y1 = std::min(t.height - 1, y + 1);
    for (int x = 0; x < t.width; ++x) {
      const int x0 = std::max(0, x - 1), x1 = std::min(t.width - 1, x + 1);
      const double dzdx = x1 > x0 ? (t.at(x1, y) - t.at(x0, y)) * k / (x1 - x0) : 0.0;
      const double dzdy = y1 > y0 ? (t.at(x, y1) - t.at(x, y0)) * k / (y1 - y0) : 0.0;
      const double len = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
      n[static_cast<std::size_t>(y) * t.width + x] = {static_cast<float>(-dzdx / len), static_cast<float>(-dzdy / len),
                                                      static_cast<float>(1.0 / len)};
    }
  }
  return n;
}

}  // namespace vbim::lighting
