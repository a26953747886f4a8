// Fault plans inside other TOML documents (config/ only; toml++ stays inside config/): the
// [[fault]] array reader behind parseFaultPlan, which in a sweep plan's fault template also takes
// ranges `{ min = ..., max = ... }` for any time or integer field (docs/sweeps.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "iop/fault_plan.hpp"

namespace vbim::iop {
class SectorSource;
}

namespace vbim::config {

// A field of fault `fault` drawn uniformly from [lo, hi] (ticks when `time`, else the integer).
struct FaultRange {
  std::size_t fault = 0;
  std::string field;
  std::int64_t lo = 0, hi = 0;
  bool time = true;
  int line = 0;
};

// Reads `node` (the `fault` value: an array of tables, or null for no faults). With `ranges`, ranged
// fields are accepted, recorded there and set to their minimum in the returned plan; without it
// they are errors. Throws ConfigError naming origin:line, the fault and the field.
iop::FaultPlan parseFaultArray(const toml::node* node, const std::string& origin, const iop::SectorSource* disc,
                               std::vector<FaultRange>* ranges);

// The checks that relate fields (and so must be repeated after a draw): overlaps of one kind, a
// random stall shorter than its interval, a contention period within its duration.
void checkDrawnFaultPlan(const iop::FaultPlan& plan, const std::string& origin);

}  // namespace vbim::config
