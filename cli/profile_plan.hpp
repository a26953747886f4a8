// `vbim profile --plan sweep.toml`: a sweep plan run on this machine (--jobs), one shard of it
// (--shard K/N), shards joined (--merge DIR) or a Slurm job array written for it (--emit-slurm DIR).
// docs/sweeps.md. The modes are calls into sweep/outputs/ (study.hpp, plan_modes.hpp); this file
// parses their options, shows progress and prints.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "runs/profile_run.hpp"
#include "sweep/outputs/study.hpp"

namespace vbim::cli {

// What `vbim profile` re-encodes streams with: FFmpeg's (sweep/outputs/reencoded_streams.hpp) in
// vbim-full; none in vbim, which hands a sweep that re-encodes to vbim-full (HandOverToFull).
struct ProfileEncoders {
  runs::Reencoder reencode;           // --qscale, --bitrate
  sweep::StreamTranscoder transcode;  // a plan's qscales, bitrates, gops
};

// Registers `vbim profile` (cli/cmd_profile.cpp).
void addProfile(CLI::App& app, const ProfileEncoders& encoders);

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
// Runs the mode asked for; a plan that re-encodes without `transcode` is handed to vbim-full.
void runPlan(const PlanRequest& r, const sweep::StreamTranscoder& transcode);

}  // namespace vbim::cli
