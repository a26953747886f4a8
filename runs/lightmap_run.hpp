// `vbim lightmap` as a library call: Technique A's day (a lighting.* TOML file over the defaults,
// the command line's values over both) on a terrain (a heightfield file, a DEM or the procedural
// one), rendered into lightmap and sky image files in an output directory written complete or not
// at all (lighting/lightmap_inputs.hpp, lighting/lightmap_files.hpp). In library vbim_lightmap_run
// (GDAL, OpenImageIO), which only vbim-full links. Not model code; no simulated time.
#pragma once

#include <functional>
#include <string>

#include "lighting/lightmap_files.hpp"
#include "lighting/terrain_file.hpp"

namespace vbim::runs {

struct LightmapRequest {
  lighting::TerrainSource terrain;  // its cellSizeGiven / verticalScaleGiven set by the caller
  std::string config;               // lighting.* TOML, or empty
  std::function<void(lighting::DayCycleParams&)> applyGiven;  // the values given, over the file's
  lighting::LightmapFilesRequest files;                       // formats, debug layers, threads
  std::string out;
  bool force = false;
};

// What the caller is told while it runs (each may be empty).
struct LightmapObserver {
  // What reading the terrain found ("HEIGHTFIELD: cropped to ..."), before any output is made.
  std::function<void(const std::string& note)> onTerrainNote;
  std::function<void(int done, int total)> onProgress;  // frames
};

// Checks the request, reads the inputs, writes the files; returns the summary ("24 frames (512x512
// lightmaps, 128x64 sky domes) in OUT"). Throws vbim::Error (lighting and config errors, an existing
// --out) naming what is wrong.
std::string lightmapRun(const LightmapRequest& r, const LightmapObserver& observer);

}  // namespace vbim::runs
