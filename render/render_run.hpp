// `vbim render` as a library call: every frame a play run saved, rendered, plus the day's contact
// sheet and the video. Also what `vbim demo` calls (docs/render.md).
//
//   const player::RunDir run = player::readRunDir(runDir);
//   render::RunRenderRequest req;                         // procedural terrain, samples' day settings
//   if (run.authoring) render::applyAuthoring(*run.authoring, runDir / "authoring.json", req);
//   runs::OutputDir dir(out, force);                      // complete or absent
//   render::RunRenderResult r = render::renderRun(run, req, dir.path(""), [](int done, int total) { ... });
//   dir.commit();
//
// Writes into `outDir` (which must exist): frames/render_NNNNNN.png (NNNNNN = the vsync),
// contact_sheet.png, playback.mp4 (MPEG-4 Part 2), render.json (settings, camera, per-frame
// hour, stream scale, sun visibility under the objects' site).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lighting/authoring/technique_a_stream.hpp"
#include "lighting/day_cycle.hpp"
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

struct RunRenderResult {
  int frames = 0;
  std::filesystem::path sheet, video;
  std::int64_t videoFrames = 0;  // frames in playback.mp4 (saved frames closer than 1/fps s are left out)
  double videoSeconds = 0;       // its length: the simulated time from the first saved frame to the run's end
  std::string context;           // GL version / renderer
  double secondsPerFrame = 0;    // host time, rendering only
};

using RenderProgressFn = std::function<void(int done, int total)>;

// Throws RenderError for any problem (no GL context, a missing or unreadable frame, a lightmap
// that does not match the terrain, a camera outside the terrain).
RunRenderResult renderRun(const player::RunDir& run, const RunRenderRequest& request,
                          const std::filesystem::path& outDir, const RenderProgressFn& progress = {});

}  // namespace vbim::render
