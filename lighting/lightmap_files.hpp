// Technique A's frames as image files (`vbim lightmap`): a lightmap and a sky dome per frame as PNG,
// EXR or GeoTIFF, frames.csv (hour, sun, key light), and the debug layers asked for (horizons, sky
// factor K, shadow mask, N.L), into one directory. docs/lighting.md.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "lighting/day_cycle.hpp"
#include "lighting/float_image.hpp"
#include "lighting/terrain_file.hpp"

namespace vbim::lighting {

struct LightmapFilesRequest {
  std::string format = "png";        // png, exr, both (png and exr), or tif (lightmaps as GeoTIFF)
  std::string debug;                 // comma-separated: horizons, sky, shadow, nl or all
  std::string layersFormat = "exr";  // float debug layers as exr, or tif (GeoTIFF)
  unsigned threads = 2;              // host threads (the files do not depend on it)
};

// Throws LightingError naming the option when `format`, `debug` or `layersFormat` is not one of
// the above: call it before any heavy work.
void checkLightmapRequest(const LightmapFilesRequest& request);

struct LightmapFiles {
  int frames = 0;
  int width = 0, height = 0;  // of the lightmaps
};

// Renders every frame of the day `params` describes on `terrain` and writes the files into `dir`
// (which exists). `progress(done, total)` is called before the first frame and after each one.
// Throws LightingError (or imageio's errors) when a file cannot be written.
LightmapFiles writeLightmapFiles(const LightmapFilesRequest& request, TerrainFile terrain, const DayCycleParams& params,
                                 FloatImage cloudTexture, const std::filesystem::path& dir,
                                 const std::function<void(int done, int total)>& progress);

}  // namespace vbim::lighting
