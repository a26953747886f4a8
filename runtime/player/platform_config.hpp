// The platform config of a run: every timing constant of every stage (drive., ring., sif., ipu.,
// gs., ee.) in one struct and one ParamTable, so a single TOML file sets them and `vbim config`
// prints them with their sources.
#pragma once

#include <string>

#include "gs/params.hpp"
#include "iop/iop_params.hpp"
#include "ipu/timing_params.hpp"
#include "runtime/params.hpp"
#include "runtime/player/ee_params.hpp"

namespace vbim::player {

struct PlatformConfig {
  iop::IopParams iop;
  ipu::IpuTimingParams ipu;
  gs::GsParams gs;
  EeParams ee;
};

void describeParams(ParamTable& t, PlatformConfig& p);
// Checks relations between parameters that single ranges cannot; throws ConfigError naming the keys.
void validate(const PlatformConfig& p);
// Defaults overlaid with a TOML document / file; validated. Throws ConfigError (file:line:key).
PlatformConfig loadPlatformToml(std::string_view text, const std::string& origin);
PlatformConfig loadPlatformFile(const std::string& path);

}  // namespace vbim::player
