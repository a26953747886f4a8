// `vbim profile --plan sweep.toml`: a sweep plan run on this machine (--jobs), one shard of it
// (--shard K/N), shards joined (--merge DIR) or a Slurm job array written for it (--emit-slurm DIR).
// docs/sweeps.md.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

struct PlanRequest {
  std::string plan;
  std::string out;
  bool force = false;
  unsigned jobs = 0;  // 0: the cores available
  bool progress = false;
  bool json = false;      // vbim profile --json: the summary as JSON (a local run only)
  std::string shard;      // "K/N"
  std::string merge;      // directory of shards
  std::string emitSlurm;  // directory for the job-array script
  unsigned shards = 0;    // 0: from the measured cost
  std::string partition;
  std::string account;
  unsigned cpusPerTask = 1;
};

// Adds the plan options to `vbim profile`.
void addPlanOptions(CLI::App& cmd, PlanRequest& r);
// True when any plan mode was asked for.
bool planMode(const PlanRequest& r);
void runPlan(const PlanRequest& r);

}  // namespace vbim::cli
