#include "runs/plan_run.hpp"

#include <chrono>
#include <filesystem>
#include <sstream>
#include <utility>
#include <vector>

#include "config/sweep_plan_toml.hpp"
#include "runs/output_dir.hpp"
#include "runs/profile_json.hpp"
#include "sweep/outputs/plan_host.hpp"
#include "sweep/outputs/plan_modes.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::runs {

namespace {

namespace fs = std::filesystem;
using sweep::CaseRecord;
using sweep::LoadedPlan;
using sweep::PlanCase;

// One mode's run: the request, the plan and how to report.
class PlanModeRun {
 public:
  PlanModeRun(const PlanRequest& r, const LoadedPlan& p, const sweep::StreamTranscoder& transcode,
              const PlanObserver& observer)
      : r_(r), p_(p), transcode_(transcode), observer_(observer) {}

  PlanResult local();
  PlanResult shard();
  PlanResult merge();
  PlanResult emitSlurm();

 private:
  void warn(const std::string& line) const {
    if (observer_.onWarning) observer_.onWarning(line);
  }
  unsigned jobs() const {
    const sweep::Jobs jobs = sweep::jobsFor(r_.jobs);
    if (!jobs.warning.empty()) warn(jobs.warning);
    return jobs.jobs;
  }
  std::vector<CaseRecord> runCases(const std::vector<PlanCase>& cases, unsigned jobs, bool measuring) const;
  sweep::PlanSummary writeOutputs(const std::vector<CaseRecord>& records, OutputDir& dir, std::ostream& text) const;
  // The outputs take their names, unless the observer stops the run first.
  void commit(OutputDir& dir) const {
    if (observer_.beforeCommit) observer_.beforeCommit();
    dir.commit();
  }

  const PlanRequest& r_;
  const LoadedPlan& p_;
  const sweep::StreamTranscoder& transcode_;
  const PlanObserver& observer_;
};

// Runs `cases`, telling the observer; then the records' warnings (not for a measured case).
std::vector<CaseRecord> PlanModeRun::runCases(const std::vector<PlanCase>& cases, unsigned jobs, bool measuring) const {
  if (observer_.onCasesStart) observer_.onCasesStart(cases.size(), measuring);
  const auto onDone = [this](const CaseRecord& rec) {
    if (observer_.onCaseDone) observer_.onCaseDone(rec);
  };
  std::vector<CaseRecord> records = sweep::runPlanCasesOf(p_, cases, jobs, onDone, transcode_);
  if (observer_.onCasesEnd) observer_.onCasesEnd();
  if (!measuring) {
    for (const std::string& w : sweep::caseWarnings(records)) warn(w);
  }
  return records;
}

// Writes the outputs and commits them; the summary lines and the files into `text`.
sweep::PlanSummary PlanModeRun::writeOutputs(const std::vector<CaseRecord>& records, OutputDir& dir,
                                             std::ostream& text) const {
  sweep::PlanSummary s = sweep::writePlanOutputs(p_, records, dir.directory(), dir.finalPath());
  commit(dir);
  for (const std::string& line : s.lines) text << line << "\n";
  text << "Open:\n";
  for (const std::string& w : s.written) text << "  " << w << "\n";
  return s;
}

PlanResult PlanModeRun::local() {
  OutputDir dir(r_.out, r_.force);  // an existing --out is refused before the sweep, not after it
  const unsigned n = jobs();
  const auto wall0 = std::chrono::steady_clock::now();  // host time: the summary only
  const std::vector<CaseRecord> records = runCases(p_.cases, n, false);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::ostringstream text;
  sweep::PlanSummary summary = writeOutputs(records, dir, text);
  PlanResult result;
  if (r_.json) {
    summary.jobs = n;
    summary.wallSeconds = wall;
    result.json = planSummaryJson(summary, result.jsonReplaced);
    return result;
  }
  text << "ran " << p_.cases.size() << " cases with " << n << " job(s) in " << sweep::fixed(wall, 1)
       << " s of host time\n";
  result.text = text.str();
  return result;
}

// One shard into --out/shard-K-of-N/ (complete or absent; no other shard's files touched).
PlanResult PlanModeRun::shard() {
  const sweep::Shard shard = sweep::selectShard(p_, r_.shard);
  OutputDir dir(fs::path(r_.out) / shard.name, r_.force);
  const std::vector<CaseRecord> records = runCases(shard.cases, jobs(), false);
  const std::size_t failed = sweep::writeShard(p_, shard.k, shard.n, records, dir.directory());
  commit(dir);
  std::ostringstream text;
  text << "shard " << shard.k << "/" << shard.n << ": cases " << shard.first << ".."
       << (shard.last == shard.first ? shard.first : shard.last - 1) << ", " << failed << " failed -> "
       << dir.finalPath().string() << "\n";
  return {text.str(), {}, false};
}

// --merge DIR: every shard-K-of-N of one N, all of this plan; the outputs a local run writes.
PlanResult PlanModeRun::merge() {
  const sweep::Merged m = sweep::mergeShards(p_, r_.plan, r_.merge);
  for (const std::string& f : m.failedShards) warn("shard " + f + ": kept in the table with status failed");
  OutputDir dir(r_.out, r_.force);
  std::ostringstream text;
  sweep::PlanSummary summary = writeOutputs(m.records, dir, text);
  PlanResult result;
  if (r_.json) {
    summary.shards = m.shards;
    result.json = planSummaryJson(summary, result.jsonReplaced);
    return result;
  }
  text << "merged " << m.shards << " shards, " << m.records.size() << " cases\n";
  result.text = text.str();
  return result;
}

// --emit-slurm DIR: a job array with one task per shard, its time and memory from a measured
// per-case cost (the slowest of up to three cases spread over the plan, run here).
PlanResult PlanModeRun::emitSlurm() {
  OutputDir dir(r_.emitSlurm, r_.force);
  const fs::path finalDir = fs::absolute(dir.finalPath());
  const sweep::SlurmRequest request{r_.shards, r_.partition, r_.account, r_.cpusPerTask};
  const sweep::EmittedSlurm e = sweep::emitSlurmJob(p_, r_.plan, request, sweep::thisProgram(), dir.directory(),
                                                    finalDir, [this](const PlanCase& c) { runCases({c}, 1, true); });
  commit(dir);
  const std::string script = (finalDir / "sweep.sbatch").string();
  std::ostringstream text;
  text << "wrote " << script << ": " << e.job.shards << " array tasks, --time " << sweep::hms(e.job.seconds)
       << ", --mem " << e.job.memMb << "M (measured " << sweep::fixed(e.perCase, 3) << " s per case)\n"
       << "submit: sbatch " << script << "\nthen:   vbim profile --plan " << r_.plan << " --merge "
       << (finalDir / "shards").string() << " --out RESULTS\n";
  return {text.str(), {}, false};
}

}  // namespace

bool planMode(const PlanRequest& r) {
  return !r.plan.empty() || !r.merge.empty() || !r.emitSlurm.empty() || !r.shard.empty();
}

sweep::LoadedPlan loadPlan(const PlanRequest& r) {
  if (r.plan.empty()) throw Error("--shard, --merge and --emit-slurm need --plan (the sweep plan)");
  const int modes = (r.shard.empty() ? 0 : 1) + (r.merge.empty() ? 0 : 1) + (r.emitSlurm.empty() ? 0 : 1);
  if (modes > 1) throw Error("give one of --shard, --merge and --emit-slurm");
  if (r.emitSlurm.empty() && r.out.empty()) throw Error("--out is required");
  if (r.json && (!r.shard.empty() || !r.emitSlurm.empty())) {
    throw Error("--json summarises a plan run here or merged (--merge), not --shard or --emit-slurm");
  }
  return sweep::loadedPlan(config::loadSweepPlan(r.plan), r.plan);
}

bool reencodes(const PlanRequest& r, const LoadedPlan& p) {
  return r.merge.empty() && sweep::reencodes(p.spec);
}

PlanResult planRun(const PlanRequest& r, const LoadedPlan& p, const sweep::StreamTranscoder& transcode,
                   const PlanObserver& observer) {
  PlanModeRun run(r, p, transcode, observer);
  if (!r.emitSlurm.empty()) return run.emitSlurm();
  if (!r.merge.empty()) return run.merge();
  if (!r.shard.empty()) return run.shard();
  return run.local();
}

}  // namespace vbim::runs
