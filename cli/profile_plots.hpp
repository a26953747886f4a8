// The results of a profile (sweep runs and stall searches) and how they are written: sweep.csv,
// stall.csv, profile.json, and the plots (plots/occupancy_*.png, plots/lag_pop_*.png,
// plots/survivable_stall.png). Shared by `vbim profile` and `vbim demo`.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cli/output_dir.hpp"
#include "cli/plot_png.hpp"
#include "cli/profile_run.hpp"

namespace vbim::cli::profile {

struct RingSize {
  std::int64_t bankmax = 5;
  std::int64_t bufmax = 160;  // sectors
};

struct SweepRun {
  std::string stream;
  RingSize ring;
  std::string faults;  // plan label ("none" or the file's stem)
  std::string policy;  // gs.catchup
  CaseResult result;
};

struct StallRow {
  std::string stream;
  RingSize ring;
  std::string policy;
  Criterion criterion = Criterion::late;
  StallResult result;
};

struct ProfileData {
  std::vector<std::pair<std::string, std::int64_t>> streamBytes;
  std::vector<SweepRun> sweep;
  std::vector<StallRow> stalls;
  StallSearch search;
};

// Writes every output into `dir` and returns the names written (relative), plots first.
std::vector<std::string> writeProfileOutputs(const ProfileData& d, const OutputDir& dir);

// The time-series figures of runs that differ in one thing (`name` of each run in the legend):
// ring occupancy (percent of the ring readable) and lag + pop per vsync.
struct NamedSeries {
  std::string name;
  RingSize ring;
  const std::vector<Sample>* series = nullptr;
};
plot::Figure occupancyFigure(const std::string& title, const std::vector<NamedSeries>& runs);
plot::Figure lagPopFigure(const std::string& title, const std::vector<NamedSeries>& runs, int popThreshold);
// Longest survivable stall against ring size (sectors), one line per stream, policy and criterion.
plot::Figure stallFigure(const std::string& title, const std::vector<StallRow>& rows, const StallSearch& search);

}  // namespace vbim::cli::profile
