// Runs the cases of a sweep plan (sweep/plan.hpp) on host threads. Each case is independent:
// its own stream handle, player, scheduler and buffers, nothing shared but read-only inputs, so a
// case's result does not depend on which thread ran it or on what ran beside it; results are
// returned by case number, and the tables written from them are the same bytes at any thread count.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sweep/plan.hpp"

namespace vbim::sweep {

// What one case gave: the run's figures (no per-vsync series) and, when measured, the stall search;
// or the error that ended it (then `ok` is false and the figures are zero).
struct CaseRecord {
  std::size_t number = 0;
  bool ok = true;
  std::string error;
  CaseResult result;
  StallResult stall;
};

// A stream of the plan for one case. Called from worker threads: must be safe to call concurrently
// and return a handle no other case reads through (file handles are not shared).
using StreamOpener = std::function<std::shared_ptr<Stream>(std::size_t stream)>;

// Told of each finished case (from one thread at a time, in order of completion).
using CaseDone = std::function<void(const CaseRecord&)>;

struct RunOptions {
  unsigned jobs = 1;
  player::Kernels kernels;
};

// Runs `cases` (a subset of expandPlan(plan), any order) with `jobs` threads; the records come back
// in the order of `cases`. A case that throws a std::exception becomes a failed record. An exception
// out of `done` (a progress report that saw Ctrl-C) stops the sweep: no case starts after it, the
// cases under way finish unreported, and it is rethrown here once every thread has joined.
std::vector<CaseRecord> runPlanCases(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                     const StreamOpener& open, const RunOptions& options, const CaseDone& done = {});

// One case on the calling thread.
CaseRecord runPlanCase(const SweepPlanSpec& plan, const PlanCase& c, const Stream& stream,
                       const player::Kernels& kernels);

}  // namespace vbim::sweep
