// The Technique A lighting options (sun, sky, clouds, moon), shared by `vbim lightmap` and
// `vbim author --terrain/--procedural`. Each option is bound to the command line's copy of its
// field and, when given, copied over the value a lighting config file set.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "lighting/day_cycle.hpp"

namespace vbim::cli {

// Option -> what it sets when it was given.
using LightingOverrides = std::vector<std::pair<CLI::Option*, std::function<void(lighting::DayCycleParams&)>>>;

// Names that differ between the two commands (`vbim author` has its own --frames and --exposure).
struct LightingOptionNames {
  std::string frames = "--frames";
  std::string exposure = "--exposure";
};

// Adds the options to `cmd`, bound to `cli` (and `noMoon`), which must outlive the parse; appends
// each to `overrides`; `added` sees every option (to group or track it).
void addLightingOptions(CLI::App* cmd, lighting::DayCycleParams& cli, bool& noMoon, LightingOverrides& overrides,
                        const LightingOptionNames& names, const std::function<void(CLI::Option*)>& added);

// Applies the options that were given, in the order they were added.
void applyGivenLightingOptions(const LightingOverrides& overrides, lighting::DayCycleParams& params);

}  // namespace vbim::cli
