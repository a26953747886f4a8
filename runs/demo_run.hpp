// `vbim demo`: the README's main job on built-in defaults. A day cycle authored from the procedural
// terrain with Technique A as the committed sample is made (lighting/authoring/sample_day.hpp), played
// through the whole pipeline with a built-in fault plan (a long drive stall, a scratched sector, loop
// wraps) into the run directory playRun writes, with the profile plots (sweep/outputs/demo_profile.hpp),
// the authored stream (day.vbim) and the saved frames rendered with OSMesa (render/) beside it: one
// output directory, complete or absent. In library vbim_demo_run (OpenImageIO, FFmpeg, Mesa through
// what it calls), apart from vbim_runs, which the lean `vbim` links.
#pragma once

#include <functional>
#include <string>

#include "runs/play_run.hpp"

namespace vbim::runs {

// The demo's faults, on the simulated clock (docs/fault-plans.md).
extern const char* const kDemoFaults;

// The demo's play: `out`, `force`, `duration` as the user gave them; the rest is the demo's own.
PlayRequest demoRequest();

struct DemoResult {
  PlayResult play;
  double profileSeconds = 0;  // host time of the profile plots (the summary only)
  int renderedFrames = 0;
  std::string renderContext;  // the OpenGL context that rendered them
};

// Runs the demo of `r` (from demoRequest()). `say` is given each line to show before the play ends
// (what is being authored, its summary, what is played), in order. `checkStop` is called between
// the steps after the play (each stall search of the profile pass, each rendered frame), where
// onSecond no longer is: it may throw to stop the demo (Ctrl-C), and the output is then not
// written. Throws vbim::Error on bad input, RunFailure when an output cannot be written or the
// rendering fails.
DemoResult demoRun(PlayRequest r, const std::function<void(const std::string& line)>& say,
                   const PlayProgressFn& onSecond, const std::function<void()>& checkStop = {});

}  // namespace vbim::runs
