// `vbim profile --plan sweep.toml`: a sweep plan run on this machine (--jobs), one shard of it
// (--shard K/N), shards joined (--merge DIR) or a Slurm job array written for it (--emit-slurm DIR).
// docs/sweeps.md. The modes are runs::planRun (runs/plan_run.hpp); this file registers their
// options, shows the cases' progress and prints.
#pragma once

#include <CLI/CLI.hpp>

#include "runs/plan_run.hpp"
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

struct PlanOptions {
  runs::PlanRequest request;
  bool progress = false;  // --progress: the cases' progress on stderr even when it is not a terminal
};

// Adds the plan options to `vbim profile`.
void addPlanOptions(CLI::App& cmd, PlanOptions& o);
// Runs the mode asked for; a plan that re-encodes without `transcode` is handed to vbim-full.
void runPlan(const PlanOptions& o, const sweep::StreamTranscoder& transcode);

}  // namespace vbim::cli
