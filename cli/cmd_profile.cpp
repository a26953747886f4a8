// vbim profile: sweeps over ring size, stream (several discs, or one re-encoded at several
// quantisers / bitrates), fault plans and catch-up policy; searches the longest drive stall each
// ring size survives; writes sweep.csv, stall.csv, profile.json and plots/*.png and *.svg into --out
// (complete or absent): runs::profileRun (runs/profile_run.hpp). docs/player.md, "Profiling".
// --plan: a sweep plan (cli/profile_plan.hpp).
#include <chrono>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/profile_plan.hpp"
#include "help/status_text.hpp"
#include "runs/play_json.hpp"
#include "runs/profile_json.hpp"
#include "runs/profile_run.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::sweep;

// Each line counts n/N over every sweep run and stall search, with the host time left at the rate
// so far (the same count plan mode's progress line shows; host time is never hashed).
class Count {
 public:
  void start(std::size_t total) {
    total_ = total;
    started_ = std::chrono::steady_clock::now();
  }
  std::string next() {
    ++done_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return help::countText(done_, total_, help::secondsLeft(elapsed, done_, total_));
  }

 private:
  std::size_t total_ = 0, done_ = 0;
  std::chrono::steady_clock::time_point started_;
};

void runProfile(const runs::ProfileRequest& r, const runs::Reencoder& reencode) {
  const auto wall0 = std::chrono::steady_clock::now();  // host time: stdout only
  auto count = std::make_shared<Count>();
  // With --json the lines are in the document at the end, not on stdout.
  std::ostream nowhere(nullptr);
  std::ostream& lines = r.json ? nowhere : std::cout;
  runs::ProfileObserver progress;
  progress.onStart = [count](std::size_t total) { count->start(total); };
  progress.sweep.onRun = [count, &lines](const SweepRun& run) {
    checkInterrupted();  // Ctrl-C between runs: the output directory is not started yet
    const runs::SweepRunReport report = runs::sweepRunReport(run);
    // The line is finished (and flushed) before the warning, so the two never share a line.
    lines << count->next() << report.line << std::endl;
    if (!report.warning.empty()) std::cerr << "vbim profile: " << report.warning << "\n";
  };
  progress.sweep.onStall = [count, &lines](const StallRow& row) {
    checkInterrupted();
    lines << count->next() << runs::stallSearchLine(row) << "\n";
  };
  progress.beforeCommit = checkInterrupted;  // a Ctrl-C while the tables and plots were written
  const runs::ProfileResult result = runs::profileRun(r, reencode, progress);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (r.json) {
    bool replaced = false;
    const std::string json = runs::profileSummaryJson(result.data, wall, result.written, replaced);
    if (replaced) std::cerr << "vbim profile: " << runs::kNotUtf8Warning << "\n";
    requestedOut() << json;
    return;
  }
  std::cout << "profiled " << result.data.sweep.size() << " sweep runs and " << result.data.stalls.size()
            << " stall searches in " << fixed(wall, 1) << " s of host time\nOpen:\n";
  for (const std::string& w : result.written) std::cout << "  " << w << "\n";
}

}  // namespace

void addProfile(CLI::App& app, const ProfileEncoders& encoders) {
  auto r = std::make_shared<runs::ProfileRequest>();
  auto plan = std::make_shared<PlanOptions>();
  auto* cmd = app.add_subcommand(kProfileCommand.name, kProfileCommand.summary);
  cmd->add_option("disc", r->discs,
                  "VBIM stream file(s) or ISO 9660 disc images; several discs are one sweep axis (not with --plan)")
      ->check(inputFile());
  cmd->add_option("--file", r->file,
                  "The stream on each disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("--config", r->config, "Platform config (TOML) the sweep starts from")->check(inputFile());
  cmd->add_option("--faults", r->faults, "Fault plan(s) to sweep (repeatable); a run without faults is always included")
      ->check(inputFile());
  cmd->add_option("--ring", r->rings, "Ring sizes BANKS:SECTORS (ring.bankmax:ring.bufmax_sectors)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--qscale", r->qscales, "Also sweep the first disc re-encoded at these quantisers (1..31)")
      ->delimiter(',');
  cmd->add_option("--bitrate", r->bitrates, "Also sweep the first disc re-encoded at these bitrates (bit/s)")
      ->delimiter(',');
  cmd->add_option("--policy", r->policies, "Catch-up policies: blend-through, hard-skip, play-late")
      ->delimiter(',')
      ->check(catchupPolicy())
      ->capture_default_str();
  cmd->add_option("--seed", r->seed, "Seed of every random draw of the model")->capture_default_str();
  cmd->add_option("--duration", r->duration, "Simulated time of each sweep run")->capture_default_str();
  cmd->add_option("--stall-at", r->stallAt, "Stall search: when the stall starts")->capture_default_str();
  cmd->add_option("--max-stall", r->maxStall, "Stall search: longest stall tried")->capture_default_str();
  cmd->add_option("--resolution", r->resolution, "Stall search: bisection stops at this width")->capture_default_str();
  cmd->add_option("--settle", r->settle, "Stall search: simulated time played after the stall ends")
      ->capture_default_str();
  cmd->add_option("--pop-threshold", r->popThreshold,
                  "Stall search: largest pop (per-byte change per vsync) allowed, or auto (the "
                  "configuration's own pop maximum without the stall)")
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-search", [r] { r->search = false; }, "Skip the survivable-stall search");
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_flag("--json", r->json,
                "Print the summary as JSON on stdout instead of a line per run (docs/cli.md, \"JSON summaries\")");
  cmd->add_option("-o,--out", r->out, "Output directory (written complete or not at all)");
  addPlanOptions(*cmd, *plan);
  cmd->footer(
      "Examples:\n"
      "  vbim profile streams/samples/day_clear.vbim --ring 4:16,5:160 --out prof/\n"
      "  vbim profile streams/samples/day_clear.vbim --faults examples/fault-plans/stall.toml --policy "
      "blend-through,hard-skip --out prof/\n"
      "  vbim profile --plan examples/sweeps/survivable-stall.toml --jobs 2 --out study/\n");
  cmd->callback([r, plan, encoders] {
    if (runs::planMode(plan->request)) {
      if (!r->discs.empty()) throw Exit(2, "a sweep plan names its streams: give --plan or stream files, not both");
      plan->request.out = r->out;
      plan->request.force = r->force;
      plan->request.json = r->json;
      return runPlan(*plan, encoders.transcode);
    }
    // `vbim` has no encoder (FFmpeg): vbim-full re-encodes (cli/main.cpp).
    if (runs::reencodes(*r) && !encoders.reencode) throw HandOverToFull{};
    runProfile(*r, encoders.reencode);
  });
}

}  // namespace vbim::cli
