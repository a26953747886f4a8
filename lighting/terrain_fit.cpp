#include "lighting/terrain_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "lighting/error.hpp"

namespace vbim::lighting {

namespace {

constexpr int kMacroblock = 16;

// Start and length of the fitted span of a side `n` texels long.
void fitSide(int n, TerrainFit fit, const std::string& origin, const char* side, int& start, int& length) {
  start = 0;
  length = n;
  if (fit == TerrainFit::None || n % kMacroblock == 0) return;
  if (fit == TerrainFit::Crop) {
    length = n / kMacroblock * kMacroblock;
    if (length == 0) {
      throw LightingError(origin + ": the " + side + " is " + std::to_string(n) +
                          " texels, too short to crop to a multiple of 16; expected at least 16 (or pad it)");
    }
  } else {
    length = (n / kMacroblock + 1) * kMacroblock;
  }
  // Centred: crop (n - length) / 2 texels off the west/north side (negative: pad), the rest off the other.
  start = (n - length) / 2;  // truncates towards zero: the odd texel goes east/south either way
}

int clampIndex(int i, int n) {
  return std::clamp(i, 0, n - 1);
}

}  // namespace

TerrainFit parseTerrainFit(const std::string& name, const std::string& what) {
  if (name == "none") return TerrainFit::None;
  if (name == "crop") return TerrainFit::Crop;
  if (name == "pad") return TerrainFit::Pad;
  throw LightingError(what + " '" + name + "': expected crop, pad or none");
}

const char* terrainFitName(TerrainFit fit) {
  switch (fit) {
    case TerrainFit::Crop:
      return "crop";
    case TerrainFit::Pad:
      return "pad";
    case TerrainFit::None:
      break;
  }
  return "none";
}

GridWindow fitWindow(int width, int height, TerrainFit fit, const std::string& origin) {
  GridWindow w;
  fitSide(width, fit, origin, "width", w.x0, w.width);
  fitSide(height, fit, origin, "height", w.y0, w.height);
  return w;
}

FloatImage windowImage(const FloatImage& image, const GridWindow& window) {
  if (image.empty()) return image;
  FloatImage out(window.width, window.height, image.channels);
  for (int y = 0; y < window.height; ++y) {
    const int sy = clampIndex(window.y0 + y, image.height);
    for (int x = 0; x < window.width; ++x) {
      const float* src = image.at(clampIndex(window.x0 + x, image.width), sy);
      std::copy(src, src + image.channels, out.at(x, y));
    }
  }
  return out;
}

Terrain windowTerrain(const Terrain& terrain, const GridWindow& window) {
  Terrain out = terrain;
  out.width = window.width;
  out.height = window.height;
  out.heights.resize(static_cast<std::size_t>(window.width) * static_cast<std::size_t>(window.height));
  for (int y = 0; y < window.height; ++y) {
    const int sy = clampIndex(window.y0 + y, terrain.height);
    for (int x = 0; x < window.width; ++x) {
      out.heights[static_cast<std::size_t>(y) * window.width + x] =
          terrain.at(clampIndex(window.x0 + x, terrain.width), sy);
    }
  }
  out.albedo = windowImage(terrain.albedo, window);
  out.bounceAlbedo = windowImage(terrain.bounceAlbedo, window);
  return out;
}

Georeference windowGeoreference(const Georeference& geo, const GridWindow& window) {
  Georeference out = geo;
  auto& gt = out.geoTransform;
  gt[0] += window.x0 * gt[1] + window.y0 * gt[2];
  gt[3] += window.x0 * gt[4] + window.y0 * gt[5];
  return out;
}

GridMapping windowMapping(const GridMapping& toGrid, const GridWindow& window) {
  return {toGrid.x0 + toGrid.dx * window.x0, toGrid.dx, toGrid.y0 + toGrid.dy * window.y0, toGrid.dy};
}

FloatImage resampleImage(const FloatImage& image, const GridMapping& m, int width, int height) {
  FloatImage out(width, height, image.channels);
  const auto c = static_cast<std::size_t>(image.channels);
  for (int y = 0; y < height; ++y) {
    const double v = std::clamp(m.y0 + m.dy * y, 0.0, image.height - 1.0);
    const int y0 = static_cast<int>(v), y1 = std::min(y0 + 1, image.height - 1);
    const double fy = v - y0;
    for (int x = 0; x < width; ++x) {
      const double u = std::clamp(m.x0 + m.dx * x, 0.0, image.width - 1.0);
      const int x0 = static_cast<int>(u), x1 = std::min(x0 + 1, image.width - 1);
      const double fx = u - x0;
      const float *a = image.at(x0, y0), *b = image.at(x1, y0), *d = image.at(x0, y1), *e = image.at(x1, y1);
      float* o = out.at(x, y);
      for (std::size_t k = 0; k < c; ++k) {
        const double top = a[k] + (b[k] - a[k]) * fx, bottom = d[k] + (e[k] - d[k]) * fx;
        o[k] = static_cast<float>(top + (bottom - top) * fy);
      }
    }
  }
  return out;
}

}  // namespace vbim::lighting
