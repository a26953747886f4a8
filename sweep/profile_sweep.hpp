// The sweep behind `vbim profile`: every stream x fault plan x catch-up policy x ring size played
// once (one case, sweep/profile_run.hpp), then for every stream x policy x ring size the longest
// survivable drive stall under both criteria. The order is fixed (streams, then plans, policies,
// rings; the stall searches after each stream's runs), so the results are the same table on every
// machine.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "iop/fault_plan.hpp"
#include "player/platform_config.hpp"
#include "sweep/profile_run.hpp"

namespace vbim::sweep {

struct RingSize {
  std::int64_t bankmax = 5;
  std::int64_t bufmax = 160;  // sectors
};

// "BANKS:SECTORS" (`vbim profile --ring 4:32`), in the ranges `vbim config --check` and `play` apply
// (iop/params.cpp): a ring they refuse (2 banks deadlock under SDK-ST's hold rule) is refused here
// too, before any case runs. Throws vbim::Error naming the text and what was expected.
RingSize parseRingSize(const std::string& text);
// Ring sizes in the order the tables list them: by sectors, then by banks.
void sortRings(std::vector<RingSize>& rings);

// `vbim profile --pop-threshold`: "auto" (-1: the configuration's own pop maximum without the
// stall) or 0..255. Throws vbim::Error naming the text.
int parsePopThreshold(const std::string& text);
// Refuses a stall search that cannot run: a bound that is not positive, or more than 100,000
// bisection steps. Throws vbim::Error naming the options.
void checkStallSearch(const StallSearch& search);

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
  Criterion criterion = Criterion::Late;
  StallResult result;
};

struct ProfileData {
  std::vector<std::pair<std::string, std::int64_t>> streamBytes;
  std::vector<SweepRun> sweep;
  std::vector<StallRow> stalls;
  StallSearch search;
};

struct SweepPlan {
  std::vector<const Stream*> streams;
  player::PlatformConfig base;                                // ring size and policy are set per case
  std::vector<std::pair<std::string, iop::FaultPlan>> plans;  // label, plan
  std::vector<std::string> policies;                          // gs.catchup names
  std::vector<RingSize> rings;
  std::uint64_t seed = 1;
  Tick duration = 0;
  bool searchStalls = true;
  StallSearch search;
  player::Kernels kernels;  // injected SIMD kernels (null: scalar references, same results)
};

// Told of each result as it is made, so a command can print progress.
struct SweepObserver {
  std::function<void(const SweepRun&)> onRun;
  std::function<void(const StallRow&)> onStall;
};

// Runs the whole sweep (throws what the player throws: streams::StreamProbeError, ConfigError,
// gs::GsError).
ProfileData runSweep(const SweepPlan& plan, const SweepObserver& observer = {});

}  // namespace vbim::sweep
