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
// Everything lands in out/demo/ together (complete or absent), and it says what to open.
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "cli/command.hpp"
#include "cli/interrupt.hpp"
#include "iop/fault_plan.hpp"
#include "lighting/authoring/sample_day.hpp"
#include "lighting/authoring/terrain_author.hpp"
#include "player/run_dir_reader.hpp"
#include "render/error.hpp"
#include "render/render_run.hpp"
#include "runs/play_run.hpp"
#include "sweep/outputs/demo_profile.hpp"

namespace vbim::cli {

namespace {

// The demo's faults, on the simulated clock (docs/fault-plans.md). The sample's whole 75 sectors fit
// in the EE's buffers after a few seconds, so the stall starts early, during the spin-up, before the first frames
// arrive.
constexpr const char* kDemoFaults = R"(# vbim demo: built-in fault plan
[[fault]]
kind = "stall"          # the drive freezes before the stream has been read: the lightmap falls behind
at = "200ms"
duration = "6s"

[[fault]]
kind = "read_error"     # a scratched sector in the stream file: drive retries, then the ring's run-up retries
lba = 2090              # file sector 42 (the bare file lies at LBA 2048)
attempts = 300
)";

}  // namespace

void addDemo(CLI::App& app) {
  auto r = std::make_shared<runs::PlayRequest>();
  r->out = "out/demo";
  r->duration = "60s";         // past the sample day's end: loop wraps (24 frames: at 24.5 s and 44.5 s)
  r->every = 240;              // about every 4 s: a rendered day on the contact sheet
  r->at = {"6s", "7s", "8s"};  // the catch-up after the stall
  r->seed = 1;
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
    namespace fs = std::filesystem;
    // The authored stream goes beside the output first and into it with the rest at commit.
    const fs::path out = runs::outputPath(r->out);
    runs::refuseExistingOutputDir(out, r->force);  // before minutes of work, not after
    const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
    fs::create_directories(parent);
    const fs::path stream = parent / ("." + out.filename().string() + ".day-" + std::to_string(::getpid()) + ".vbim");
    struct Cleanup {
      fs::path p;
      ~Cleanup() {
        std::error_code ec;
        fs::remove(p, ec);
      }
    } cleanup{stream};
    std::cout << "vbim demo: authoring a day cycle from the procedural terrain (Technique A)\n";
    // The sample's recipe, so that the demo's stream and the committed sample cannot drift apart (a
    // test checks they are byte-identical).
    const lighting::TechniqueAStreamSettings recipe = lighting::sampleDaySettings();
    // Named as it is kept in the output (day.vbim), never by its temporary name: the summary and
    // stats.json's run.disc.path are the same on every run.
    r->disc = stream.string();
    r->discLabel = "day.vbim";
    std::cout << lighting::authoredSummary((out / r->discLabel).string(), lighting::authorTechniqueA(recipe, stream),
                                           recipe.stream.encoder.containerFps);
    if (iop::parseDuration(r->duration) <= fromMs(8'000)) r->at.clear();  // the catch-up shots lie past a short run
    r->faultsText = kDemoFaults;
    std::cout << "vbim demo: playing it with a 6 s drive stall at 0.2 s, a read error at LBA 2090 and loop wraps\n";
    auto prof = std::make_shared<sweep::DemoProfile>();
    auto rendered = std::make_shared<render::RunRenderResult>();
    r->onRow = [prof](const player::VsyncRow& row) { prof->onRow(row); };
    // The hooks live in *r, so they reach it through a plain pointer: capturing the shared_ptr would
    // make the request own itself (LeakSanitizer).
    runs::PlayRequest* req = r.get();
    r->beforeCommit = [prof, req, rendered, stream](const runs::OutputDir& dir) {
      prof->write(req->disc, dir.directory());
      std::error_code ec;
      fs::copy_file(stream, dir.path("day.vbim"), fs::copy_options::overwrite_existing, ec);
      if (ec) throw Exit(2, dir.path("day.vbim").string() + ": cannot copy the authored stream: " + ec.message());
      fs::create_directories(dir.path("render"));
      try {
        // The terrain and day the stream was authored with, from the record play copied.
        player::RunDir run = player::readRunDir(dir.path(""));
        run.path = "..";  // render.json names the run as seen from render/, not the temporary directory
        render::RunRenderRequest request;
        if (run.authoring) render::applyAuthoring(*run.authoring, "authoring.json", request);
        *rendered = render::renderRun(run, request, dir.path("render"), [](int, int) {});
      } catch (const render::RenderError& e) {
        throw Exit(1, std::string("rendering failed: ") + e.what());
      }
    };
    printPlayResult(exitOneOnRunFailure([&] { return runs::playRun(*r, [](double, double) { checkInterrupted(); }); }));
    std::cout << "profile pass (plots, survivable-stall curve): " << static_cast<int>(prof->seconds() * 10) / 10.0
              << " s of host time; rendered " << rendered->frames << " frames (" << rendered->context << ")\n";
    const std::string shown = out.string();  // "--out dd/" is shown as dd
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
