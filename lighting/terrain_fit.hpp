// Fitting a terrain to a stream's frame size: MPEG-2 pictures are whole 16x16 macroblocks
// (docs/stream-format.md), so `vbim author` crops or pads a heightfield whose sides are not
// multiples of 16, centred, and moves its georeference with it (docs/lighting.md#dem-input). Colour
// maps given on the heightfield file's own grid follow the terrain through the same steps.
#pragma once

#include <string>

#include "lighting/float_image.hpp"
#include "lighting/georeference.hpp"
#include "lighting/terrain.hpp"

namespace vbim::lighting {

enum class TerrainFit {
  None,  // leave the sides as they are (the encoder refuses sides that are not multiples of 16)
  Crop,  // down to a multiple of 16, the same number of texels off each side (one more off the east/south)
  Pad,   // up to a multiple of 16, the edge heights and colours repeated outwards
};

// "none", "crop" or "pad"; throws LightingError naming `what` and the choices otherwise.
TerrainFit parseTerrainFit(const std::string& name, const std::string& what);
const char* terrainFitName(TerrainFit fit);

// A window of a grid: texel (x, y) of the window is texel (x0 + x, y0 + y) of the grid; a padded
// window starts at negative coordinates and reaches past the grid.
struct GridWindow {
  int x0 = 0, y0 = 0, width = 0, height = 0;
};

// The window `fit` makes of a width x height grid (the whole grid when the sides already are
// multiples of 16, or for TerrainFit::None). Throws LightingError (naming `origin`) when cropping a
// side shorter than 16.
GridWindow fitWindow(int width, int height, TerrainFit fit, const std::string& origin);

// The terrain (heights, albedo, bounce albedo) cut to the window; texels outside repeat the nearest edge.
Terrain windowTerrain(const Terrain& terrain, const GridWindow& window);
FloatImage windowImage(const FloatImage& image, const GridWindow& window);
// The georeference of the window's grid: the origin moves by (x0, y0) texels.
Georeference windowGeoreference(const Georeference& geo, const GridWindow& window);

// Where a grid's texel centres lie on another grid, in that grid's texel indices:
// u = x0 + dx * x, v = y0 + dy * y (a negative step for a flipped axis).
struct GridMapping {
  double x0 = 0, dx = 1, y0 = 0, dy = 1;
};
// The mapping of the window's texels onto the grid `toGrid` maps to.
GridMapping windowMapping(const GridMapping& toGrid, const GridWindow& window);

// `image` (on the grid `mapping` points into) sampled bilinearly at every texel of a width x height
// grid; positions outside are clamped to the edge texels.
FloatImage resampleImage(const FloatImage& image, const GridMapping& mapping, int width, int height);

}  // namespace vbim::lighting
