// Platform configs: the defaults of every timing constant (player::PlatformConfig) overlaid with a
// TOML file, then checked for relations single ranges cannot express. docs/timing-model.md lists
// the keys; `vbim config --defaults` prints them.
#pragma once

#include <string>
#include <string_view>

#include "player/platform_config.hpp"

namespace vbim::config {

// Defaults overlaid with a TOML document / file; validated. Throws ConfigError (file:line:key).
player::PlatformConfig loadPlatformToml(std::string_view text, const std::string& origin);
player::PlatformConfig loadPlatformFile(const std::string& path);

}  // namespace vbim::config
