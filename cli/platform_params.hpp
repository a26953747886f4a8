// The platform config: every timing constant of every component (drive., ring., sif., ipu., gs.,
// ee.), gathered in one ParamTable so a single TOML file sets them and `vbim config` prints them with
// their sources. The struct itself lives with the player (player/platform_config.hpp), which
// the test API shares; this header keeps the CLI's names.
#pragma once

#include <string>

#include "gs/error.hpp"
#include "player/platform_config.hpp"
#include "runtime/param_table.hpp"

namespace vbim::cli {

using PlatformParams = player::PlatformConfig;

void describePlatform(ParamTable& t, PlatformParams& p);
// Checks relations between parameters (after loading); throws ConfigError.
void validatePlatform(const PlatformParams& p);

// A GsError about the platform config, said the same way by every command: `FILE:LINE: key 'gs.x':
// message` for the first of its keys (by line) that the config file FILE sets; `FILE: message` when
// the file sets none of them; `the default platform config: message` without a file.
std::string gsConfigMessage(const gs::GsError& e, const std::string& configPath);

// A `--policy` value checked against gs::kCatchupPolicies (throws Exit 2 naming the choices).
std::string catchupPolicy(const std::string& name);

}  // namespace vbim::cli
