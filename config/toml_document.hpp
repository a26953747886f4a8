// One TOML document parsed, with syntax errors as ConfigError naming the file and line: shared by
// the platform config and fault plan readers. Internal to config/ (toml++ stays inside it).
#pragma once

#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace vbim::config {

toml::table parseTomlDocument(std::string_view text, const std::string& origin);

}  // namespace vbim::config
