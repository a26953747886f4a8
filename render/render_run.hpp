// `vbim render` as a library call: every frame a play run saved, rendered, plus the day's contact
// sheet and the video. Also what `vbim demo` calls (docs/render.md).
//
//   const player::RunDir run = player::readRunDir(runDir);
//   render::RunRenderRequest req;                         // procedural terrain, samples' day settings
//   if (run.authoring) render::applyAuthoring(*run.authoring, runDir / "authoring.json", req);
//   (or render::requestForRun: the record with a command line's options over it, render/run_request.hpp)
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

#include "player/run_dir_reader.hpp"
#include "render/run_request.hpp"

namespace vbim::render {

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
