// Sweep plans from TOML (docs/sweeps.md) into the plain sweep::SweepPlanSpec: axes,
// fault-plan templates with their seeded draws made here, measures and probabilities. Errors name
// file:line: key and what was expected (ConfigError).
#pragma once

#include <string>
#include <string_view>

#include "sweep/plan.hpp"

namespace vbim::config {

// `baseDir` resolves relative paths in the plan (streams, config, fault-plan files): the plan
// file's folder. Throws ConfigError.
sweep::SweepPlanSpec parseSweepPlan(std::string_view text, const std::string& origin, const std::string& baseDir);
sweep::SweepPlanSpec loadSweepPlan(const std::string& path);

}  // namespace vbim::config
