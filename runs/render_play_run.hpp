// `vbim render RUN --out DIR` as a library call: the frames a `vbim play --every N --out RUN` saved,
// rendered (render/render_run.hpp) with the request render::requestForRun makes of the run's
// authoring record and the given options (render/run_request.hpp), into an output directory written
// complete or not at all. In library vbim_render_play_run (OSMesa, FFmpeg), which only vbim-full
// links. Not model code; no simulated time.
#pragma once

#include <functional>
#include <string>

#include "render/run_request.hpp"

namespace vbim::runs {

struct RenderPlayRequest {
  std::string run;  // the play's run directory
  std::string out;
  std::string camera;                 // "EX,EZ,EH,TX,TZ" (render::parseCamera), or empty: the default view
  render::RunRequestOptions options;  // every option that reaches render::requestForRun
  bool force = false;
};

// What the caller is told while it runs (each may be empty).
struct RenderPlayObserver {
  // What was assumed when the run does not say what terrain it shows, before any output is made.
  std::function<void(const std::string& note)> onNote;
  std::function<void(int done, int total)> onProgress;  // frames
};

// Reads the run, renders, writes; returns what `vbim render` prints (the frames rendered, with which
// GL context and how fast, and the files to open). Throws vbim::Error (render::RenderError for a run,
// record, lighting config or camera that cannot be used; an existing --out) naming what is wrong.
std::string renderPlayRun(const RenderPlayRequest& r, const RenderPlayObserver& observer);

}  // namespace vbim::runs
