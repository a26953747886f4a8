// The results of a profile (sweep runs and stall searches) and how they are written: sweep.csv,
// stall.csv, profile.json, and the figures, drawn by plots/profile_figures.hpp from the plain
// results (plots/occupancy_*, plots/lag_pop_*, plots/survivable_stall, each .png and .svg).
// Shared by `vbim profile` and `vbim demo`.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "plots/profile_figures.hpp"
#include "sweep/profile_sweep.hpp"

namespace vbim::sweep {

// The runs and the sweep are sweep/profile_run.hpp's and sweep/profile_sweep.hpp's; this file writes
// their results into a directory (the caller makes it complete or absent: runs/output_dir.hpp).

// `v` with `decimals` digits after the point (C locale), for the tables and the command's lines.
std::string fixed(double v, int decimals);

// Writes every output into `dir` and returns the names written (relative), plots first.
std::vector<std::string> writeProfileOutputs(const ProfileData& d, const std::filesystem::path& dir);

// stall.csv: one row per stall search (ring, policy, criterion), the longest stall survived. Also
// `vbim demo`'s plots/survivable_stall.csv.
void writeStallCsv(const std::vector<StallRow>& rows, const StallSearch& search, std::ostream& o);

// The plain inputs of the figures.
std::vector<plots::profile::TracePoint> tracePoints(const std::vector<Sample>& series);
std::vector<plots::profile::StallPoint> stallPoints(const std::vector<StallRow>& rows);
plots::profile::StallSearchSetup stallSearchSetup(const StallSearch& search);

}  // namespace vbim::sweep
