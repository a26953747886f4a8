#include "cli/profile_plan.hpp"

#include <unistd.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <string>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "help/status_text.hpp"
#include "runs/play_json.hpp"

namespace vbim::cli {

namespace {

// The cases' progress on stderr (n/N, failures, time left): redrawn on a terminal, or one line every
// few seconds when --progress asks for it elsewhere (never for the cases --emit-slurm measures).
class CaseProgress {
 public:
  explicit CaseProgress(bool forced) : forced_(forced) {}

  void start(std::size_t total, bool measuring) {
    bar_.reset();  // a measured case's line is ended before the next one starts
    bar_.emplace("vbim profile", "cases", forced_ && !measuring);
    total_ = total;
    done_ = failed_ = 0;
    start_ = lastShown_ = std::chrono::steady_clock::now();  // host time: the progress line only
  }
  void done(const sweep::CaseRecord& rec) {
    ++done_;
    if (!rec.ok) ++failed_;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (!terminal_ && done_ < total_ && now - lastShown_ < std::chrono::seconds(5)) return;
    lastShown_ = now;
    const std::string left = help::clockText(help::secondsLeft(elapsed, done_, total_));
    bar_->show(static_cast<double>(done_), static_cast<double>(total_),
               std::to_string(failed_) + " failed, " + left + " left");
  }
  void end() { bar_->finish(); }

 private:
  bool forced_;
  bool terminal_ = ::isatty(STDERR_FILENO) == 1;
  std::optional<Progress> bar_;
  std::size_t total_ = 0, done_ = 0, failed_ = 0;
  std::chrono::steady_clock::time_point start_, lastShown_;
};

}  // namespace

void addPlanOptions(CLI::App& cmd, PlanOptions& o) {
  runs::PlanRequest& r = o.request;
  cmd.add_option("--plan", r.plan, "Sweep plan (TOML, docs/sweeps.md): run its cases instead of the options above");
  cmd.add_option("--jobs", r.jobs, "Sweep plan: cases run at once (default: the cores available)");
  cmd.add_flag("--progress", o.progress, "Sweep plan: progress on stderr even when it is not a terminal");
  cmd.add_option("--shard", r.shard, "Sweep plan: run only shard K of N into --out/shard-K-of-N");
  cmd.add_option("--merge", r.merge, "Sweep plan: join the shards in this directory into --out");
  cmd.add_option("--emit-slurm", r.emitSlurm, "Sweep plan: write a Slurm job-array script and the plan here");
  cmd.add_option("--shards", r.shards, "--emit-slurm: array tasks (default: about 10 minutes of cases each)");
  cmd.add_option("--partition", r.partition, "--emit-slurm: the Slurm partition");
  cmd.add_option("--account", r.account, "--emit-slurm: the Slurm account");
  cmd.add_option("--cpus-per-task", r.cpusPerTask, "--emit-slurm: cores per array task (its --jobs)")
      ->capture_default_str();
}

void runPlan(const PlanOptions& o, const sweep::StreamTranscoder& transcode) {
  const sweep::LoadedPlan p = runs::loadPlan(o.request);
  // `vbim` has no encoder (FFmpeg): vbim-full runs a plan that re-encodes (cli/main.cpp).
  if (runs::reencodes(o.request, p) && !transcode) throw HandOverToFull{};
  CaseProgress progress(o.progress);
  runs::PlanObserver observer;
  observer.onCasesStart = [&progress](std::size_t total, bool measuring) { progress.start(total, measuring); };
  observer.onCaseDone = [&progress](const sweep::CaseRecord& rec) { progress.done(rec); };
  observer.onCasesEnd = [&progress] { progress.end(); };
  observer.onWarning = [](const std::string& line) { std::cerr << "vbim profile: " << line << "\n"; };
  observer.beforeCommit = checkInterrupted;  // a Ctrl-C while the tables and plots were written
  const runs::PlanResult result = runs::planRun(o.request, p, transcode, observer);
  if (o.request.json) {
    if (result.jsonReplaced) std::cerr << "vbim profile: " << runs::kNotUtf8Warning << "\n";
    requestedOut() << result.json;
  } else {
    std::cout << result.text;
  }
}

}  // namespace vbim::cli
