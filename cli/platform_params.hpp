// The platform config: every timing constant of every component, gathered in one ParamTable so a
// single TOML file sets them and `vbim config` prints them with their sources. Components join as
// their issues land; the player (issue #7) takes this over.
#pragma once

#include "iop/iop_params.hpp"
#include "runtime/params.hpp"

namespace vbim::cli {

struct PlatformParams {
  iop::IopParams iop;
};

void describePlatform(ParamTable& t, PlatformParams& p);
// Checks relations between parameters (after loading); throws ConfigError.
void validatePlatform(const PlatformParams& p);

}  // namespace vbim::cli
