// vbim demo: the README's main job. Plays the committed sample stream streams/samples/day_clear.vbim
// through the whole pipeline with a built-in fault plan (a long drive stall, a scratched sector, and
// a run past the loop point so the stream wraps), writes everything `vbim play` writes into
// out/demo/, and says what to open. Needs nothing downloaded.
//
// The stream is found next to the binary (../streams/samples or streams/samples) or in the source
// tree this binary was built from (VBIM_SOURCE_DIR). A later step makes the demo author its own
// stream from Technique A first: replace demoStream() with that.
#include <filesystem>
#include <iostream>

#include "cli/command.hpp"
#include "cli/play_run.hpp"
#include "iop/fault_plan.hpp"

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

std::filesystem::path demoStream() {
  namespace fs = std::filesystem;
  const fs::path rel = fs::path("streams") / "samples" / "day_clear.vbim";
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (fs::path dir = exe.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
      if (fs::exists(dir / rel)) return dir / rel;
    }
  }
#ifdef VBIM_SOURCE_DIR
  if (fs::exists(fs::path(VBIM_SOURCE_DIR) / rel)) return fs::path(VBIM_SOURCE_DIR) / rel;
#endif
  if (fs::exists(rel)) return rel;
  throw Exit(2, "vbim demo: cannot find " + rel.string() +
                    " next to the binary or in the source tree; run from the repository root or pass a stream to "
                    "`vbim play`");
}

}  // namespace

void addDemo(CLI::App& app) {
  auto r = std::make_shared<PlayRequest>();
  r->out = "out/demo";
  r->duration = "60s";         // past the 48-frame day's end at 48.5 s: one loop wrap
  r->every = 600;              // about every 10 s
  r->at = {"6s", "7s", "8s"};  // the catch-up after the stall
  r->seed = 1;
  r->force = true;  // the demo owns out/demo and replaces it
  auto* cmd = app.add_subcommand("demo", "Run the main job on built-in defaults and write everything to out/demo/");
  cmd->add_option("--out", r->out, "Output directory (replaced)")->capture_default_str();
  cmd->add_option("--duration", r->duration, "Simulated time")->capture_default_str();
  static double seconds = 0.0;  // CLI11 writes here; lives as long as the app
  cmd->add_option("--seconds", seconds, "Simulated seconds (the same as --duration Ns)")
      ->check(CLI::Range(0.001, 86400.0))
      ->each([r](const std::string& v) { r->duration = v + "s"; });
  cmd->callback([r] {
    r->disc = demoStream().string();
    if (iop::parseDuration(r->duration) <= fromMs(8'000)) r->at.clear();  // the catch-up shots lie past a short run
    r->faultsText = kDemoFaults;
    std::cout << "vbim demo: " << r->disc << " with a 6 s drive stall at 0.2 s, a read error at LBA 2090 and a loop "
              << "wrap at 48.5 s\n";
    std::cout << runPlay(*r, false);
    std::cout << "Open:\n"
              << "  " << r->out << "/trace.json    in https://ui.perfetto.dev (busy spans, ring occupancy, pop, lag)\n"
              << "  " << r->out << "/signals.vcd   in GTKWave\n"
              << "  " << r->out << "/stats.json    busy shares, ring occupancy, late/dropped/caught-up frames, damage\n"
              << "  " << r->out << "/timeline.csv  one row per vsync (pop, lag, targets, ring banks)\n"
              << "  " << r->out << "/frames/       lightmap and sky images (PNG)\n";
  });
}

}  // namespace vbim::cli
