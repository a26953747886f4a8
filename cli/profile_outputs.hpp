// The results of a profile (sweep runs and stall searches) and how they are written: sweep.csv,
// stall.csv, profile.json, and the figures, drawn by plots/profile_figures.hpp from the plain
// results (plots/occupancy_*, plots/lag_pop_*, plots/survivable_stall, each .png and .svg).
// Shared by `vbim profile` and `vbim demo`.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cli/output_dir.hpp"
#include "player/profile_sweep.hpp"
#include "plots/profile_figures.hpp"

namespace vbim::cli::profile {

// The runs and the sweep are the player's (player/profile_run.hpp, player/profile_sweep.hpp); this
// file writes their results.
using namespace vbim::player::profile;

// `v` with `decimals` digits after the point (C locale), for the tables and the command's lines.
std::string fixed(double v, int decimals);

// Writes every output into `dir` and returns the names written (relative), plots first.
std::vector<std::string> writeProfileOutputs(const ProfileData& d, const OutputDir& dir);

// The plain inputs of the figures.
std::vector<plots::profile::TracePoint> tracePoints(const std::vector<Sample>& series);
std::vector<plots::profile::StallPoint> stallPoints(const std::vector<StallRow>& rows);
plots::profile::StallSearchSetup stallSearchSetup(const StallSearch& search);

}  // namespace vbim::cli::profile
