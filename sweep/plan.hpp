// A sweep plan as the player runs it (read from TOML by config/sweep_plan_toml.hpp; docs/sweeps.md):
// axes whose product is the list of cases, the measures to take, and the probabilities to estimate
// over the Monte Carlo axes (fault-template draws and seeds). Plain data: no file or TOML here.
//
// Case order (fixed, so case numbers and tables are the same on every machine and at any --jobs):
// streams, then platform variants, fault templates, policies, rings, seeds, and the template's draws
// innermost; case k of the product is case number k.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "iop/fault_plan.hpp"
#include "player/platform_config.hpp"
#include "sweep/profile_run.hpp"
#include "sweep/profile_sweep.hpp"

namespace vbim::sweep {

// A stream axis value: a file, optionally re-encoded (bitrate in bit/s or quantiser; 0: as is) with
// a GOP structure (gop 1: every picture intra; bFrames B pictures between references; closed GOPs
// unless openGop), as `vbim author --gop --b-frames --open-gop` writes them.
struct StreamSpec {
  std::string label;
  std::string path;
  std::int64_t bitrate = 0;
  int qscale = 0;
  int gop = 1;
  int bFrames = 0;
  bool openGop = false;
  bool reencoded() const { return bitrate != 0 || qscale != 0; }
};

// `[equal_quality]` (docs/gop-study.md): per GOP structure of the `gops` axis, the re-encode whose
// mean PSNR against the source is nearest the reference's (the re-encode with gop referenceGop,
// referenceBFrames B pictures, at referenceQscale); "equal" when within toleranceDb of it.
struct EqualQuality {
  int referenceGop = 1;
  int referenceBFrames = 0;
  int referenceQscale = 0;
  double toleranceDb = 0.25;
};

// A platform axis value: the keys it sets (as written, for the table) and the config they make.
struct PlatformVariant {
  std::vector<std::pair<std::string, std::string>> values;  // key, value as text
  player::PlatformConfig config;
};

// One drawn fault plan of a template: the plan and what was drawn ("stall.duration=1.25s; ...").
struct FaultDraw {
  iop::FaultPlan plan;
  std::string drawn;
};

// A fault-plan template: `draws` seeded variants (one when nothing in it is random).
struct FaultTemplate {
  std::string name;
  std::vector<FaultDraw> draws;
};

// What a case measures (docs/sweeps.md, "Measures"); each adds its columns to the table.
// Coding (bitrate, sectors per frame, GOP, PSNR against the source) and BusyShare (the IPU's and the
// EE's) came last: a table's existing columns keep their order.
enum class Measure {
  FramesLate,
  FramesDropped,
  FramesCaughtUp,
  PopMax,
  LagMax,
  RingOccupancy,
  SurvivableStall,
  Coding,
  BusyShare
};
const char* toString(Measure m);

// P(measure op threshold), estimated per group of cases that differ only in Monte Carlo axes.
struct Probability {
  std::string name;
  std::string measure;  // a column of the table: frames_late, pop_max, longest_stall_s, ...
  std::string op;       // ">", ">=", "<", "<="
  double threshold = 0;
};

struct SweepPlanSpec {
  std::vector<StreamSpec> streams;
  std::vector<PlatformVariant> platforms;  // at least one (the base config)
  std::vector<std::string> platformKeys;   // the keys any variant sets, in order of first appearance
  std::vector<FaultTemplate> faults;       // at least one ("none": no faults)
  std::vector<std::string> policies;
  std::vector<RingSize> rings;
  std::vector<std::uint64_t> seeds;
  Tick duration = 0;
  std::vector<Measure> measures;  // in table order
  Criterion stallCriterion = Criterion::Late;
  StallSearch search;
  std::vector<Probability> probabilities;
  std::optional<EqualQuality> equalQuality;
};

// One case: indices into the plan's axes. Its run seed is seeds[seed] + draw, so the random faults
// of the run differ from draw to draw.
struct PlanCase {
  std::size_t number = 0;
  std::size_t stream = 0, platform = 0, faults = 0, policy = 0, ring = 0, seed = 0, draw = 0;
  std::uint64_t runSeed(const SweepPlanSpec& p) const { return p.seeds[seed] + draw; }
};

// Every case of the plan, in case order.
std::vector<PlanCase> expandPlan(const SweepPlanSpec& plan);

// The case numbers of shard k (1-based) of n: a contiguous block, sizes differing by at most one.
std::pair<std::size_t, std::size_t> shardRange(std::size_t cases, std::size_t k, std::size_t n);

bool hasMeasure(const SweepPlanSpec& plan, Measure m);

}  // namespace vbim::sweep
