// The platform config of a run: every timing constant of every stage (drive., ring., sif., ipu.,
// gs., ee.) in one struct and one ParamTable, so a single TOML file sets them and `vbim config`
// prints them with their sources.
#pragma once

#include <string>

#include "ee/params.hpp"
#include "gs/params.hpp"
#include "iop/params.hpp"
#include "ipu/params.hpp"
#include "runtime/param_table.hpp"

namespace vbim::player {

struct PlatformConfig {
  iop::IopParams iop;
  ipu::IpuParams ipu;
  gs::GsParams gs;
  ee::EeParams ee;
};

void describeParams(ParamTable& t, PlatformConfig& p);
// Checks relations between parameters that single ranges cannot; throws ConfigError naming the keys.
void validate(const PlatformConfig& p);

}  // namespace vbim::player
