// The terrain the generator lights: a heightfield on a square grid, optionally with a diffuse
// colour (albedo) map of the same size.
//
// Axes (docs/lighting.md#axes-and-azimuth): e1 = +column (east), e2 = +row (south; image rows go down),
// up = height. Every vector in lighting/ (normals, sun direction, horizon azimuths) uses this
// (col, row, up) basis, so azimuth a counts from east towards south (clockwise seen from above).
//
// Heights are integers (height units of `heightStep` metres): the horizon scans compare slopes by
// exact integer cross products, which is what makes the O(n) hull scan bit-identical to brute force.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lighting/float_image.hpp"

namespace vbim::lighting {

// Heights are limited to +-2^24 units so slope cross products fit in int64 with room to spare.
inline constexpr std::int32_t kMaxHeightUnits = 1 << 24;

struct Vec3 {
  float x = 0, y = 0, z = 0;
};

struct Terrain {
  int width = 0;
  int height = 0;
  double cellSize = 10.0;             // metres between neighbouring texel centres
  double heightStep = 0.01;           // metres per height unit
  std::vector<std::int32_t> heights;  // width * height, row-major
  FloatImage albedo;                  // RGB, linear, width x height; empty = uniform `defaultAlbedo`
  float defaultAlbedo = 0.3f;         // assumption: typical vegetated terrain, 0.15-0.35
  // Optional albedo of the terrain a texel sees, for the coloured bounce light of the Stewart-Langer
  // term only (docs/lighting.md#interreflection); empty = the texel's own albedo.
  FloatImage bounceAlbedo;

  std::int32_t at(int x, int y) const { return heights[static_cast<std::size_t>(y) * width + x]; }
  double metresAt(int x, int y) const { return at(x, y) * heightStep; }
  std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
  // Albedo of texel i, channel c (0..2).
  float albedoAt(std::size_t i, int c) const {
    return albedo.empty() ? defaultAlbedo : albedo.pixels[i * 3 + static_cast<std::size_t>(c)];
  }
  float bounceAlbedoAt(std::size_t i, int c) const {
    return bounceAlbedo.empty() ? albedoAt(i, c) : bounceAlbedo.pixels[i * 3 + static_cast<std::size_t>(c)];
  }
};

// Builds a terrain from heights in metres. Fails (LightingError naming `origin`, the pixel and
// what was expected) on an empty grid, a NaN or infinite height, or a non-positive cell size.
// Heights are quantised to a step of at most 1/256 m (larger only for relief over 32 km).
Terrain terrainFromMetres(int width, int height, const std::vector<float>& metres, double cellSize,
                          const std::string& origin);

// Builds a terrain from integer samples (a 16-bit PNG's counts) kept exactly: one unit per count.
Terrain terrainFromCounts(int width, int height, const std::vector<std::uint32_t>& counts, double cellSize,
                          double metresPerCount, const std::string& origin);

// Attaches an RGB albedo map; it must have the terrain's size and 3 channels, values finite.
void setAlbedo(Terrain& terrain, FloatImage albedo, const std::string& origin);
// The same for the bounce-light albedo (`Terrain::bounceAlbedo`).
void setBounceAlbedo(Terrain& terrain, FloatImage albedo, const std::string& origin);

// Unit surface normals in the (col, row, up) basis: N ~ (-dz/dcol, -dz/drow, 1) with central
// differences (one-sided at the border) scaled by the cell size.
std::vector<Vec3> terrainNormals(const Terrain& terrain);

}  // namespace vbim::lighting
