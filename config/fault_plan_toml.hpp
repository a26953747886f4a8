// Fault plans from TOML (docs/fault-plans.md) into the plain iop::FaultPlan the model arms on the
// drive. Anything malformed, unknown, negative, overlapping or out of range is rejected with
// file:line, the fault's kind and the field.
#pragma once

#include <string>
#include <string_view>

#include "iop/fault_plan.hpp"
#include "runtime/error.hpp"

namespace vbim::iop {
class SectorSource;
}

namespace vbim::config {

// Parses a plan. `disc` (optional) resolves `file = "..."` and checks LBAs against the disc. Throws
// ConfigError (runtime/error.hpp), naming the file, the line, the fault and the field.
iop::FaultPlan parseFaultPlan(std::string_view text, const std::string& origin,
                              const iop::SectorSource* disc = nullptr);
iop::FaultPlan loadFaultPlan(const std::string& path, const iop::SectorSource* disc = nullptr);

}  // namespace vbim::config
