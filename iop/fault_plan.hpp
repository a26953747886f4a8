// Fault plans: timed events that disturb the drive, on the simulated clock and nowhere else.
// Written as TOML (read by config/fault_plan_toml.hpp), one [[fault]] table per event, `kind` naming what it is
// (docs/fault-plans.md):
//   stall         at, duration                      the drive freezes
//   read_error    lba, attempts [, from]            the sector fails its next N read attempts
//   seek_away     at, lba | file, sectors           another file is read (level data, audio)
//   contention    from, duration, share [, period, lba | file]  another client takes share % of drive time
//   random_stall  from, duration, mean_interval, stall          seeded stalls at a mean rate
//   random_error  from, duration, per_million [, attempts]      seeded sector errors at a rate
// Times are strings with a unit: "12.5s", "800ms", "250us". Anything malformed, unknown,
// negative, overlapping or out of range is rejected with file:line and the field.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/clock.hpp"
#include "runtime/rng.hpp"
#include "runtime/scheduler.hpp"

namespace vbim::iop {

class SectorSource;
class Drive;

struct Fault {
  enum class Kind { Stall, ReadError, SeekAway, Contention, RandomStall, RandomError };
  Kind kind = Kind::Stall;
  int line = 0;       // line of the [[fault]] header in the plan
  Tick at = 0;        // stall, seek_away: when; others: start of the interval ("from")
  Tick duration = 0;  // stall, contention, random_*: length
  std::int64_t lba = -1;
  std::int64_t sectors = 0;
  std::int64_t attempts = 0;
  std::int64_t share = 0;       // contention: percent of drive time
  Tick period = 0;              // contention: slice period
  Tick meanInterval = 0;        // random_stall
  Tick stallLength = 0;         // random_stall
  std::int64_t perMillion = 0;  // random_error
};

struct FaultPlan {
  std::string origin;
  std::vector<Fault> faults;

  // Parsed from TOML by config/fault_plan_toml.hpp; the model sees only this plain list.
};

const char* toString(Fault::Kind k);

// The longest time a plan, a duration or an instant may give: 10^10 s (317 years). Sums of a few
// such times (from + duration, the lead before playback, a stall after it) stay far below the
// largest tick count (2^63 - 1 ticks = 6.2 x 10^10 s).
inline constexpr Tick kMaxTime = 10'000'000'000 * kBusHz;

// Parses "12.5s", "800ms", "250us" into ticks (nearest tick, integer arithmetic). Throws
// std::invalid_argument with the reason, also for a time longer than kMaxTime.
Tick parseDuration(std::string_view text);

// The shortest contention period and random-stall mean interval a plan may ask for: one sector's
// read at the disc's inner edge (1,080 sectors/s in CAV, docs/timing/iop.md). Another client cannot
// take the drive in slices finer than one of its own reads, and the bound keeps a plan's cost to
// at most a few thousand faults per entry and simulated second (a 50 ns period made 20 M drive
// commands per simulated second; found by fault_plan_toml_fuzzer). An assumption of the model.
inline constexpr Tick kMinFaultInterval = fromMs(1);

// A contention entry's slice of each period: period x share / 100, in 128 bits.
Tick contentionSlice(const Fault& f);

// Arms the plan on a drive: stalls and sector faults become drive hooks; random stalls are drawn
// from `rng` (a fork of the run seed) as the clock reaches them; seek-aways and contention slices
// are issued, as the clock reaches them, by a process named "faults" as another IOP client would.
// Cost: memory per plan entry and time per fault that falls in the simulated time played.
void applyFaults(Scheduler& s, Drive& drive, const FaultPlan& plan, Rng rng);

}  // namespace vbim::iop
