// vbim demo: the README's main job, on built-in defaults with nothing downloaded.
//  1. Authors a day cycle from the procedural terrain with Technique A, exactly as the committed
//     sample streams/samples/day_clear.vbim is made (lighting/authoring/sample_day.hpp).
//  2. Plays it through the whole pipeline with a built-in fault plan (a long drive stall, a
//     scratched sector, and a run past the loop point so the stream wraps), writing everything
//     `vbim play` writes into out/demo/.
//  3. Adds the profile plots (occupancy, lag and pop over time, the survivable-stall curve:
//     sweep/outputs/demo_profile.hpp).
//  4. Renders the saved frames with OSMesa: terrain, sky and hemisphere-lit objects, a contact sheet
//     with the stall and catch-up marked, and a video.
// Everything lands in out/demo/ together (complete or absent): runs::demoRun (runs/demo_run.hpp); this
// file says what to open.
#include <iostream>

#include "cli/command.hpp"
#include "cli/interrupt.hpp"
#include "runs/demo_run.hpp"

namespace vbim::cli {

void addDemo(CLI::App& app) {
  auto r = std::make_shared<runs::PlayRequest>(runs::demoRequest());
  auto* cmd = app.add_subcommand(kDemoCommand.name, kDemoCommand.summary);
  cmd->add_option("-o,--out", r->out, "Output directory (written complete or not at all)")->capture_default_str();
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory (scripts/demo.sh passes it)");
  cmd->add_option("--duration", r->duration, "Simulated time")->capture_default_str();
  static double seconds = 0.0;  // CLI11 writes here; lives as long as the app
  cmd->add_option("--seconds", seconds, "Simulated seconds (the same as --duration Ns)")
      ->check(CLI::Range(0.001, 86400.0))
      ->each([r](const std::string& v) { r->duration = v + "s"; });
  cmd->footer(
      "Examples:\n"
      "  vbim demo\n"
      "  vbim demo --out dd/ --duration 20s\n");
  cmd->callback([r] {
    const runs::DemoResult result = runs::demoRun(
        *r, [](const std::string& line) { std::cout << line; }, [](double, double) { checkInterrupted(); },
        [] { checkInterrupted(); });
    printPlayResult(result.play);
    std::cout << "profile pass (plots, survivable-stall curve): " << static_cast<int>(result.profileSeconds * 10) / 10.0
              << " s of host time; rendered " << result.renderedFrames << " frames (" << result.renderContext << ")\n";
    const std::string shown = runs::outputPath(r->out).string();  // "--out dd/" is shown as dd
    std::cout << "Open:\n"
              << "  " << shown << "/trace.json    in https://ui.perfetto.dev (busy spans, ring occupancy, pop, lag)\n"
              << "  " << shown << "/signals.vcd   in GTKWave\n"
              << "  " << shown << "/stats.json    busy shares, ring occupancy, late/dropped/caught-up frames, damage\n"
              << "  " << shown << "/timeline.csv  one row per vsync (pop, lag, targets, ring banks)\n"
              << "  " << shown << "/frames/       lightmap and sky images (PNG)\n"
              << "  " << shown << "/plots/occupancy.png         stream ring occupancy over time\n"
              << "  " << shown << "/plots/lag_pop.png           lag and pop over time\n"
              << "  " << shown << "/plots/survivable_stall.png  longest stall survived against ring size "
              << "(vbim profile sweeps more)\n"
              << "  " << shown << "/render/contact_sheet.png    the day, rendered, stall and catch-up marked\n"
              << "  " << shown << "/render/playback.mp4         the playback as video\n"
              << "  " << shown << "/day.vbim                    the authored stream (vbim info / vbim play it)\n";
  });
}

}  // namespace vbim::cli
