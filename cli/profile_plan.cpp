#include "cli/profile_plan.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/progress.hpp"
#include "config/sweep_plan_toml.hpp"
#include "runs/output_dir.hpp"
#include "runs/profile_json.hpp"
#include "sweep/outputs/plan_host.hpp"
#include "sweep/outputs/plan_modes.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::cli {

namespace {

namespace fs = std::filesystem;
using sweep::CaseRecord;
using sweep::LoadedPlan;
using sweep::PlanCase;

unsigned jobsFor(const PlanRequest& r) {
  const sweep::Jobs jobs = sweep::jobsFor(r.jobs);
  if (!jobs.warning.empty()) std::cerr << "vbim profile: " << jobs.warning << "\n";
  return jobs.jobs;
}

std::string clock(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  char b[32];
  if (s >= 3600) {
    std::snprintf(b, sizeof b, "%lldh%02lldm", s / 3600, s / 60 % 60);
  } else {
    std::snprintf(b, sizeof b, "%lldm%02llds", s / 60, s % 60);
  }
  return b;
}

// Runs `cases` with progress on stderr (n/N, failures, time left): redrawn on a terminal, or one
// line every few seconds when --progress asks for it elsewhere; then the records' warnings.
std::vector<CaseRecord> runCases(const LoadedPlan& p, const std::vector<PlanCase>& cases, unsigned jobs,
                                 bool forceProgress, const sweep::StreamTranscoder& transcode) {
  Progress bar("vbim profile", "cases", forceProgress);
  const auto start = std::chrono::steady_clock::now();  // host time: the progress line only
  auto lastShown = start;
  std::size_t done = 0, failed = 0;
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  auto onDone = [&](const CaseRecord& rec) {
    ++done;
    if (!rec.ok) ++failed;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (!terminal && done < cases.size() && now - lastShown < std::chrono::seconds(5)) return;
    lastShown = now;
    bar.show(static_cast<double>(done), static_cast<double>(cases.size()),
             std::to_string(failed) + " failed, " + clock(secondsLeft(elapsed, done, cases.size())) + " left");
  };
  std::vector<CaseRecord> records = sweep::runPlanCasesOf(p, cases, jobs, onDone, transcode);
  bar.finish();
  return records;
}

void warn(const std::vector<CaseRecord>& records) {
  for (const std::string& w : sweep::caseWarnings(records)) std::cerr << "vbim profile: " << w << "\n";
}

// Writes the outputs; prints the summary lines and the files (and returns them, for --json).
sweep::PlanSummary writeAll(const LoadedPlan& p, const std::vector<CaseRecord>& records, runs::OutputDir& dir,
                            bool json) {
  sweep::PlanSummary s = sweep::writePlanOutputs(p, records, dir.directory(), dir.finalPath());
  dir.commit();
  if (json) return s;
  for (const std::string& line : s.lines) std::cout << line << "\n";
  std::cout << "Open:\n";
  for (const std::string& w : s.written) std::cout << "  " << w << "\n";
  return s;
}

void runLocal(const PlanRequest& r, const LoadedPlan& p, const sweep::StreamTranscoder& transcode) {
  runs::OutputDir dir(r.out, r.force);  // an existing --out is refused before the sweep, not after it
  const unsigned jobs = jobsFor(r);
  const auto wall0 = std::chrono::steady_clock::now();
  const std::vector<CaseRecord> records = runCases(p, p.cases, jobs, r.progress, transcode);
  warn(records);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  sweep::PlanSummary summary = writeAll(p, records, dir, r.json);
  if (r.json) {
    summary.jobs = jobs;
    summary.wallSeconds = wall;
    requestedOut() << runs::planSummaryJson(summary);
    return;
  }
  std::cout << "ran " << p.cases.size() << " cases with " << jobs << " job(s) in " << sweep::fixed(wall, 1)
            << " s of host time\n";
}

// One shard into --out/shard-K-of-N/ (complete or absent; no other shard's files touched).
void runShard(const PlanRequest& r, const LoadedPlan& p, const sweep::StreamTranscoder& transcode) {
  const sweep::Shard shard = sweep::selectShard(p, r.shard);
  runs::OutputDir dir(fs::path(r.out) / shard.name, r.force);
  const std::vector<CaseRecord> records = runCases(p, shard.cases, jobsFor(r), r.progress, transcode);
  warn(records);
  const std::size_t failed = sweep::writeShard(p, shard.k, shard.n, records, dir.directory());
  dir.commit();
  std::cout << "shard " << shard.k << "/" << shard.n << ": cases " << shard.first << ".."
            << (shard.last == shard.first ? shard.first : shard.last - 1) << ", " << failed << " failed -> "
            << dir.finalPath().string() << "\n";
}

// --merge DIR: every shard-K-of-N of one N, all of this plan; the outputs a local run writes.
void runMerge(const PlanRequest& r, const LoadedPlan& p) {
  sweep::Merged m;
  try {
    m = sweep::mergeShards(p, r.plan, r.merge);
  } catch (const sweep::MissingShards& e) {
    throw Exit(3, e.what());
  }
  for (const std::string& f : m.failedShards)
    std::cerr << "vbim profile: shard " << f << ": kept in the table with status failed\n";
  runs::OutputDir dir(r.out, r.force);
  sweep::PlanSummary summary = writeAll(p, m.records, dir, r.json);
  if (r.json) {
    summary.shards = static_cast<std::size_t>(m.shards);
    requestedOut() << runs::planSummaryJson(summary);
    return;
  }
  std::cout << "merged " << m.shards << " shards, " << m.records.size() << " cases\n";
}

// --emit-slurm DIR: a job array with one task per shard, its time and memory from a measured
// per-case cost (the slowest of up to three cases spread over the plan, run here).
void emitSlurm(const PlanRequest& r, const LoadedPlan& p, const sweep::StreamTranscoder& transcode) {
  runs::OutputDir dir(r.emitSlurm, r.force);
  const fs::path finalDir = fs::absolute(dir.finalPath());
  const sweep::SlurmRequest request{r.shards, r.partition, r.account, r.cpusPerTask};
  const sweep::EmittedSlurm e = sweep::emitSlurmJob(p, r.plan, request, sweep::thisProgram(), dir.directory(), finalDir,
                                                    [&](const PlanCase& c) { runCases(p, {c}, 1, false, transcode); });
  dir.commit();
  std::cout << "wrote " << (finalDir / "sweep.sbatch").string() << ": " << e.job.shards << " array tasks, --time "
            << sweep::hms(e.job.seconds) << ", --mem " << e.job.memMb << "M (measured " << sweep::fixed(e.perCase, 3)
            << " s per case)\n"
            << "submit: sbatch " << (finalDir / "sweep.sbatch").string() << "\nthen:   vbim profile --plan " << r.plan
            << " --merge " << (finalDir / "shards").string() << " --out RESULTS\n";
}

}  // namespace

void addPlanOptions(CLI::App& cmd, PlanRequest& r) {
  cmd.add_option("--plan", r.plan, "Sweep plan (TOML, docs/sweeps.md): run its cases instead of the options above");
  cmd.add_option("--jobs", r.jobs, "Sweep plan: cases run at once (default: the cores available)");
  cmd.add_flag("--progress", r.progress, "Sweep plan: progress on stderr even when it is not a terminal");
  cmd.add_option("--shard", r.shard, "Sweep plan: run only shard K of N into --out/shard-K-of-N");
  cmd.add_option("--merge", r.merge, "Sweep plan: join the shards in this directory into --out");
  cmd.add_option("--emit-slurm", r.emitSlurm, "Sweep plan: write a Slurm job-array script and the plan here");
  cmd.add_option("--shards", r.shards, "--emit-slurm: array tasks (default: about 10 minutes of cases each)");
  cmd.add_option("--partition", r.partition, "--emit-slurm: the Slurm partition");
  cmd.add_option("--account", r.account, "--emit-slurm: the Slurm account");
  cmd.add_option("--cpus-per-task", r.cpusPerTask, "--emit-slurm: cores per array task (its --jobs)")
      ->capture_default_str();
}

bool planMode(const PlanRequest& r) {
  return !r.plan.empty() || !r.merge.empty() || !r.emitSlurm.empty() || !r.shard.empty();
}

void runPlan(const PlanRequest& r, const sweep::StreamTranscoder& transcode) {
  if (r.plan.empty()) throw Exit(2, "--shard, --merge and --emit-slurm need --plan (the sweep plan)");
  const int modes = (r.shard.empty() ? 0 : 1) + (r.merge.empty() ? 0 : 1) + (r.emitSlurm.empty() ? 0 : 1);
  if (modes > 1) throw Exit(2, "give one of --shard, --merge and --emit-slurm");
  if (r.emitSlurm.empty() && r.out.empty()) throw Exit(2, "--out is required");
  if (r.json && (!r.shard.empty() || !r.emitSlurm.empty())) {
    throw Exit(2, "--json summarises a plan run here or merged (--merge), not --shard or --emit-slurm");
  }
  const LoadedPlan p = sweep::loadedPlan(config::loadSweepPlan(r.plan), r.plan);
  // `vbim` has no encoder (FFmpeg): vbim-full runs a plan that re-encodes (cli/main.cpp). A merge
  // re-encodes nothing.
  if (r.merge.empty() && sweep::reencodes(p.spec) && !transcode) throw HandOverToFull{};
  if (!r.emitSlurm.empty()) return emitSlurm(r, p, transcode);
  if (!r.merge.empty()) return runMerge(r, p);
  if (!r.shard.empty()) return runShard(r, p, transcode);
  runLocal(r, p, transcode);
}

}  // namespace vbim::cli
