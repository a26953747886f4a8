// `vbim profile --plan`'s modes as calls: a plan's outputs from its records (run here or merged),
// what to warn of in the records, one shard's cases, and a Slurm job array sized from measured cases.
// runs::planRun (runs/plan_run.hpp) puts them in order; the command (cli/profile_plan.cpp) shows
// progress and prints what it returns.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/outputs/study.hpp"

namespace vbim::sweep {

// The warnings the records call for, each a line without the command's prefix: up to five failed
// cases with their errors and a count of the rest, then stuck and starved runs, which are findings,
// not failures (counted once, listed in the table's health column).
std::vector<std::string> caseWarnings(const std::vector<CaseRecord>& records);

// A plan run here or merged from shards: its summary lines and the files written, with the facts of
// the run (how many cases, jobs and host time; or shards merged), for the lines and --json.
struct PlanSummary {
  std::vector<std::string> lines;  // summaryLines (sweep/outputs/table.hpp)
  std::size_t cases = 0;
  unsigned jobs = 0;        // run here: the jobs; 0 for a merge
  double wallSeconds = -1;  // run here: the host time; < 0 for a merge
  std::size_t shards = 0;   // merged: the shards joined; 0 for a run here
  std::vector<std::string> written;
};

// Writes the plan's outputs (sweep/outputs/table.hpp) into `dir`, which will be moved to `finalDir`:
// the summary lines, the number of cases and the written files as they will be named.
PlanSummary writePlanOutputs(const LoadedPlan& p, const std::vector<CaseRecord>& records,
                             const std::filesystem::path& dir, const std::filesystem::path& finalDir);

// `--shard K/N`: where shard K lies in the plan's cases, its cases and its directory's name.
struct Shard {
  std::size_t k = 0, n = 0;
  std::size_t first = 0, last = 0;  // cases [first, last)
  std::vector<PlanCase> cases;
  std::string name;  // shard-K-of-N
};
Shard selectShard(const LoadedPlan& p, const std::string& text);

// `--emit-slurm`: a few cases run through `runCase` and measured (measureCaseCost), the job array
// sized from them and its files written into `dir` (to be moved to `finalDir`), each task running
// `program`.
struct EmittedSlurm {
  SlurmJob job;
  double perCase = 0;  // host seconds of the slowest measured case
};
EmittedSlurm emitSlurmJob(const LoadedPlan& p, const std::string& planPath, const SlurmRequest& request,
                          const std::string& program, const std::filesystem::path& dir,
                          const std::filesystem::path& finalDir, const std::function<void(const PlanCase&)>& runCase);

// This program's path (/proc/self/exe), which a Slurm task runs; "vbim" when it cannot be read.
std::string thisProgram();

}  // namespace vbim::sweep
