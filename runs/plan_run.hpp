// `vbim profile --plan sweep.toml` as library calls: the request checked and the plan read, then the
// mode asked for: the plan run on this machine (--jobs), one shard of it (--shard K/N), the shards
// joined (--merge DIR) or a Slurm job array written for it (--emit-slurm DIR), each output directory
// complete or absent (docs/sweeps.md). The modes' parts are sweep/outputs/ (study.hpp,
// plan_modes.hpp, plan_host.hpp); this file puts them in order. Not model code (TOML, files); the
// host time it measures goes to the summary line and the Slurm sizing only, never into a table.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "sweep/outputs/study.hpp"

namespace vbim::runs {

struct PlanRequest {
  std::string plan;  // the sweep plan (TOML)
  std::string out;
  bool force = false;
  unsigned jobs = 0;      // 0: the cores available
  bool json = false;      // the summary as JSON (a plan run here or merged)
  std::string shard;      // "K/N"
  std::string merge;      // directory of shards
  std::string emitSlurm;  // directory for the job-array script
  unsigned shards = 0;    // --emit-slurm's array tasks; 0: from the measured cost
  std::string partition;
  std::string account;
  unsigned cpusPerTask = 1;
};

// True when any plan mode was asked for (--plan, --shard, --merge or --emit-slurm).
bool planMode(const PlanRequest& r);

// The request checked (a plan, one mode, an --out where one is written, --json only where there is a
// summary) and the plan read (config::loadSweepPlan). Throws vbim::Error naming what is wrong.
sweep::LoadedPlan loadPlan(const PlanRequest& r);

// True when the mode asked for re-encodes a stream of the plan (its qscales, bitrates or gops; a
// merge re-encodes nothing): planRun needs a StreamTranscoder for it.
bool reencodes(const PlanRequest& r, const sweep::LoadedPlan& p);

// What the caller is told while the cases run (each callback may be empty).
struct PlanObserver {
  // `total` cases start: the plan's or the shard's, or (`measuring`) the one case at a time whose
  // cost --emit-slurm measures.
  std::function<void(std::size_t total, bool measuring)> onCasesStart;
  // Each case as it ends, one thread at a time (sweep/runner.hpp).
  std::function<void(const sweep::CaseRecord&)> onCaseDone;
  // The cases of the last onCasesStart ended.
  std::function<void()> onCasesEnd;
  // A warning as it arises (more jobs than cores, failed or stuck cases, failed shards merged), one
  // line without the command's prefix.
  std::function<void(const std::string&)> onWarning;
  // Once the outputs are written, just before they take their names: a throw here (the command's
  // Ctrl-C check) leaves no output, as a stop during the cases does.
  std::function<void()> beforeCommit;
};

struct PlanResult {
  std::string text;           // the lines for stdout: the summary, the files written, what ran
  std::string json;           // with PlanRequest::json: the document instead (runs/profile_json.hpp)
  bool jsonReplaced = false;  // its bytes not UTF-8 written as U+FFFD: the command warns (kNotUtf8Warning)
};

// Runs the mode asked for on `p` (loadPlan(r)), re-encoding through `transcode`. Throws vbim::Error
// on bad input (an existing --out, a bad shard, shards of another plan), sweep::MissingShards when a
// merge lacks shards, and throws before anything is written, where it can.
PlanResult planRun(const PlanRequest& r, const sweep::LoadedPlan& p, const sweep::StreamTranscoder& transcode,
                   const PlanObserver& observer);

}  // namespace vbim::runs
