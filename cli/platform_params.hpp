// The platform config: every timing constant of every component (drive., ring., sif., ipu., gs.,
// ee.), gathered in one ParamTable so a single TOML file sets them and `vbim config` prints them with
// their sources. The struct itself lives with the player (player/platform_config.hpp), which
// the test API shares; this header keeps the CLI's names.
#pragma once

#include <string>

#include "player/platform_config.hpp"
#include "runtime/params.hpp"

namespace vbim::cli {

using PlatformParams = player::PlatformConfig;

void describePlatform(ParamTable& t, PlatformParams& p);
// Checks relations between parameters (after loading); throws ConfigError.
void validatePlatform(const PlatformParams& p);

// A `--policy` value checked against gs::kCatchupPolicies (throws Exit 2 naming the choices).
std::string catchupPolicy(const std::string& name);

}  // namespace vbim::cli
