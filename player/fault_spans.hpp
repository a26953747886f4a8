// When the drive was disturbed during a run, as spans of simulated time, for pictures that show it
// (the contact sheet's fault strip, the plots' shading): the fault plan's timed entries, and the
// read errors as the drive met them (a sector's error has no time in the plan, only an LBA).
// RunDirWriter writes them to faults.csv (`kind,begin_s,end_s`, docs/run-files.md); the run
// directory reader and `vbim demo`'s plots read them back.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "iop/fault_plan.hpp"
#include "runtime/clock.hpp"

namespace vbim::player {

struct FaultSpan {
  std::string kind;  // "stall", "read error", "contention", "seek away", "random stalls", "random errors"
  double beginS = 0, endS = 0;
  friend bool operator==(const FaultSpan&, const FaultSpan&) = default;
};

// The plan's entries that have a time, clipped to [0, duration): a stall from `at` for its
// duration; contention and the random kinds over their interval; a seek-away as one vsync's
// instant (1/60 s). Read errors are not among them (see ReadErrorSpans).
std::vector<FaultSpan> plannedFaultSpans(const iop::FaultPlan& plan, Tick duration);

// Read errors as they happened: told the drive's retry count at every vsync, it makes one span per
// run of vsyncs at which the count grew, from the vsync before the first growth to the last one.
class ReadErrorSpans {
 public:
  void onVsync(Tick at, std::int64_t retriesSoFar);
  std::vector<FaultSpan> spans() const;

 private:
  std::vector<FaultSpan> done_;
  std::int64_t retries_ = 0;
  Tick previous_ = 0;
  Tick openBegin_ = -1, openEnd_ = 0;
};

// Both, ordered by begin (then kind).
std::vector<FaultSpan> mergeFaultSpans(std::vector<FaultSpan> planned, const std::vector<FaultSpan>& observed);

// faults.csv: a header `kind,begin_s,end_s` and a row per span, times with 6 decimals.
void writeFaultSpansCsv(std::ostream& out, const std::vector<FaultSpan>& spans);
// Reads faults.csv; a missing file gives no spans. Throws vbim::Error naming file:line for a row
// that does not parse.
std::vector<FaultSpan> readFaultSpansCsv(const std::filesystem::path& file);

}  // namespace vbim::player
