// The figures of a profile (`vbim profile`, and the profile pass of `vbim demo`), from its plain
// results: ring occupancy over time, lag and pop over time, and the longest survivable drive stall
// against ring size. What the numbers mean: docs/player.md, "Profiling".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "plots/chart.hpp"

namespace vbim::plots::profile {

// One vsync of a run.
struct TracePoint {
  double t = 0;       // simulated seconds
  int ringBanks = 0;  // banks of the stream ring readable
  int lag = 0;        // largest per-byte difference from the fault-free run (8-bit levels)
  int pop = 0;        // largest per-byte change of the lightmap in this vsync (8-bit levels)
};

// A run's trace; `name` is its legend entry, `bankmax` banks are 100 % of its ring.
struct RunTrace {
  std::string name;
  std::int64_t bankmax = 5;
  std::vector<TracePoint> points;
};

// A time the drive was disturbed (a run's faults.csv row, player/fault_spans.hpp): shaded on the
// time axis of the occupancy and lag/pop figures, in a colour per kind, named in the legend.
struct FaultInterval {
  std::string kind;  // "stall", "read error", "contention", "seek away", "random stalls", "random errors"
  double beginS = 0, endS = 0;
};

// The bands for `faults`: pale colours per kind, legend names that say what each is.
std::vector<Band> faultBands(const std::vector<FaultInterval>& faults);

// One result of a stall search: the line it belongs to (legend name, e.g. stream, policy and
// criterion), the ring size, and the longest stall survived (none: fails even without a stall).
struct StallPoint {
  std::string line;
  double ringSectors = 0;
  std::optional<double> longestS;
};

struct StallSearchSetup {
  double stallAtS = 0;
  double maxStallS = 0;
  int popThreshold = -1;  // -1: auto
};

// Ring occupancy (percent of the ring readable) over time, one line per run; `faults` shaded.
Figure occupancyFigure(const std::string& title, const std::vector<RunTrace>& runs,
                       const std::vector<FaultInterval>& faults = {});
// Lag and pop over time (two panels), one line per run; a dashed threshold when popThreshold >= 0;
// `faults` shaded in both panels.
Figure lagPopFigure(const std::string& title, const std::vector<RunTrace>& runs, int popThreshold,
                    const std::vector<FaultInterval>& faults = {});
// Longest survivable stall against ring size (log2 axis), one line per StallPoint::line in order of
// first appearance, with the search limit dashed.
Figure stallFigure(const std::string& title, const std::vector<StallPoint>& points, const StallSearchSetup& setup);

// A sweep run of `vbim profile`: what it varied and its trace (RunTrace::name is left to this).
struct SweepTrace {
  std::string stream;
  std::string faults;  // plan label ("none" or the file's stem)
  std::string policy;  // catch-up policy
  std::int64_t bankmax = 5;
  std::int64_t bufmax = 160;  // sectors
  std::vector<TracePoint> points;
  std::vector<FaultInterval> faultSpans;  // the drive's faults in this run, shaded
};

// Writes the figures of `vbim profile` into `dir`, each as .png and .svg: one
// plots/occupancy_<stream>_<faults>_<policy> and one plots/lag_pop_<...> per stream, fault plan
// and policy (a line per ring size; the faults of its first run shaded: the same plan, and read
// errors as the first ring met them), and plots/survivable_stall when there are stall results.
// Returns the names written, relative to `dir`. Throws Error.
std::vector<std::string> writeProfileFigures(const std::vector<SweepTrace>& sweep,
                                             const std::vector<StallPoint>& stalls, const StallSearchSetup& setup,
                                             const std::filesystem::path& dir);

}  // namespace vbim::plots::profile
