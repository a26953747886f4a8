// vbim demo: the README's main job. Plays the committed sample stream streams/samples/day_clear.vbim
// through the whole pipeline with a built-in fault plan (a long drive stall, a scratched sector, and
// a run past the loop point so the stream wraps), writes everything `vbim play` writes into
// out/demo/, and says what to open. Needs nothing downloaded.
//
// The stream is found next to the binary (../streams/samples or streams/samples) or in the source
// tree this binary was built from (VBIM_SOURCE_DIR). A later step makes the demo author its own
// stream from Technique A first: replace demoStream() with that.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/command.hpp"
#include "cli/play_run.hpp"
#include "cli/profile_plots.hpp"
#include "cli/profile_run.hpp"
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

// The demo's profile pass: the occupancy, lag and pop of the demo run itself, and a small
// survivable-stall curve (five ring sizes, blend-through, both criteria) on the same stream. A few
// seconds of host time.
class DemoProfile {
 public:
  void onRow(const player::VsyncRow& row) {
    profile::Sample s;
    s.t = toSeconds(row.at);
    s.ringBanks = static_cast<int>(row.ringBanks);
    s.lag = row.lag;
    s.pop = shown_ ? row.lightmap.pop : 0;  // the first frame copied into the empty lightmap is no pop
    shown_ = shown_ || row.lightmap.targetSeq >= 0;
    s.behind = row.lightmap.behind;
    series_.push_back(s);
  }
  void write(const std::string& disc, const OutputDir& dir) {
    namespace pr = profile;
    const auto wall0 = std::chrono::steady_clock::now();
    std::filesystem::create_directories(dir.path("plots"));
    const pr::RingSize demoRing{player::PlatformConfig{}.iop.ring.bankmax,
                                player::PlatformConfig{}.iop.ring.bufmax_sectors};
    const std::vector<pr::NamedSeries> runs{{"vbim demo (ring 160 sectors, 5 banks)", demoRing, &series_}};
    const std::string title = "vbim demo: day_clear with a 6 s stall at 0.2 s, a read error and a loop wrap";
    plot::writePng(pr::occupancyFigure(title, runs), dir.path("plots/occupancy.png"));
    plot::writePng(pr::lagPopFigure(title, runs, -1), dir.path("plots/lag_pop.png"));

    const auto stream = pr::bareStream(disc);
    pr::StallSearch search;
    search.stallAt = fromMs(3'000);
    search.maxStall = fromMs(20'000);
    search.resolution = fromMs(100);
    search.settle = fromMs(5'000);
    std::vector<pr::StallRow> rows;
    for (const pr::RingSize ring :
         {pr::RingSize{4, 8}, pr::RingSize{4, 16}, pr::RingSize{4, 32}, pr::RingSize{4, 64}, pr::RingSize{5, 160}}) {
      pr::Case c;
      c.stream = stream.get();
      c.config.iop.ring.bankmax = ring.bankmax;
      c.config.iop.ring.bufmax_sectors = ring.bufmax;
      for (pr::Criterion crit : {pr::Criterion::late, pr::Criterion::pop})
        rows.push_back(
            pr::StallRow{stream->label, ring, c.config.gs.catchup, crit, pr::longestSurvivableStall(c, search, crit)});
    }
    plot::writePng(pr::stallFigure("vbim demo: survivable drive stall against ring size", rows, search),
                   dir.path("plots/survivable_stall.png"));
    std::ofstream csv(dir.path("plots/survivable_stall.csv"), std::ios::binary);
    csv << "bankmax,bufmax_sectors,policy,criterion,longest_stall_s,saturated\n";
    for (const pr::StallRow& r : rows) {
      csv << r.ring.bankmax << "," << r.ring.bufmax << "," << r.policy << "," << pr::toString(r.criterion) << ","
          << (r.result.longest ? std::to_string(toSeconds(*r.result.longest)) : std::string()) << ","
          << (r.result.saturated ? 1 : 0) << "\n";
    }
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  }
  double seconds() const { return seconds_; }

 private:
  std::vector<profile::Sample> series_;
  bool shown_ = false;
  double seconds_ = 0;
};

}  // namespace

void addDemo(CLI::App& app) {
  auto r = std::make_shared<PlayRequest>();
  r->out = "out/demo";
  r->duration = "60s";         // past the sample day's end: loop wraps (24 frames: at 24.5 s and 44.5 s)
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
    std::cout << "vbim demo: " << r->disc << " with a 6 s drive stall at 0.2 s, a read error at LBA 2090 and loop "
              << "wraps\n";
    auto prof = std::make_shared<DemoProfile>();
    r->onRow = [prof](const player::VsyncRow& row) { prof->onRow(row); };
    r->beforeCommit = [prof, r](const OutputDir& dir) { prof->write(r->disc, dir); };
    std::cout << runPlay(*r, false);
    std::cout << "profile pass (plots, survivable-stall curve): " << static_cast<int>(prof->seconds() * 10) / 10.0
              << " s of host time\n";
    std::cout << "Open:\n"
              << "  " << r->out << "/trace.json    in https://ui.perfetto.dev (busy spans, ring occupancy, pop, lag)\n"
              << "  " << r->out << "/signals.vcd   in GTKWave\n"
              << "  " << r->out << "/stats.json    busy shares, ring occupancy, late/dropped/caught-up frames, damage\n"
              << "  " << r->out << "/timeline.csv  one row per vsync (pop, lag, targets, ring banks)\n"
              << "  " << r->out << "/frames/       lightmap and sky images (PNG)\n"
              << "  " << r->out << "/plots/occupancy.png         stream ring occupancy over time\n"
              << "  " << r->out << "/plots/lag_pop.png           lag and pop over time\n"
              << "  " << r->out << "/plots/survivable_stall.png  longest stall survived against ring size "
              << "(vbim profile sweeps more)\n";
  });
}

}  // namespace vbim::cli
