// What `vbim render` renders a run with: the terrain and day the stream was authored with (the
// run's authoring record, authoring.json), defaults for a run without one, and the command line's
// options over either (docs/render.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lighting/day_cycle.hpp"
#include "lighting/terrain_file.hpp"
#include "player/run_dir_reader.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"

namespace vbim::render {

struct RunRenderRequest {
  RenderSettings settings;
  // The terrain and lighting that made the stream: from the run's authoring.json (applyAuthoring)
  // when the stream carried a record. Default, for streams without one: the procedural terrain at
  // the lightmap's size (20 m cells) and a 24-frame day from 0 h to 24 h, 45 deg N, 21 June.
  lighting::TerrainSource terrain;
  bool proceduralSizeFromLightmap = true;
  lighting::DayCycleParams day;
  // The lighting of each stream variant (weather), by variant number, from the authoring record: a
  // frame is lit as the variant the timeline says it shows (after a branch, another weather). Empty:
  // `day` for every frame (a run without a record).
  std::vector<lighting::DayCycleParams> variantDays;
  int loopFrame = 0;
  int videoFps = 10;  // the video's clock: ticks per second (it plays at the run's speed at any value)
  int sheetColumns = 6;
  int sheetThumbWidth = 200;
  bool video = true;
  std::string settingsFrom = "defaults";  // where terrain and day came from (render.json)
  GlContextFactory contextFactory = defaultContextFactory();

  RunRenderRequest();
};

// Loads `path` (TOML, lighting.* keys as `vbim config --defaults` lists them) into day; throws
// RenderError with file:line:key.
void loadLightingConfig(const std::string& path, lighting::DayCycleParams& day);

// Takes terrain (source, cell size, size), day (the first variant's lighting.* settings: frame
// count, hours, site, sky), every variant's settings (variantDays) and loop frame from an authoring
// record (`origin` names it). Throws RenderError naming the origin and the field for a record that
// cannot be read.
void applyAuthoring(const std::string& record, const std::string& origin, RunRenderRequest& request);

// The options of `vbim render` that reach the request: every one's value (given or default) and
// which were given.
struct RunRequestOptions {
  RunRenderRequest values;     // settings, terrain, day, loop frame, video: given or default
  std::string terrain;         // --terrain, or empty
  std::string albedo;          // --albedo, or empty
  std::string lightingConfig;  // --lighting-config, or empty
  // Given on the command line: they win over the authoring record's.
  bool cellSize = false, verticalScale = false, relief = false, terrainSeed = false, loopFrame = false;
};

// The request for `run`: its authoring record when it has one (a record of a stream made from
// image files or the synthetic generator holds no terrain: the defaults), else the defaults; the
// given options over it either way, a lighting config's keys over every variant's day. `note` gets
// the line saying what was assumed when the run does not say what terrain it shows. Throws
// RenderError for a record or a lighting config that cannot be read.
RunRenderRequest requestForRun(const player::RunDir& run, const RunRequestOptions& options,
                               const std::function<void(const std::string&)>& note);

}  // namespace vbim::render
