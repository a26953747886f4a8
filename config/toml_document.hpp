// One TOML document parsed, with syntax errors as ConfigError naming the file and line: shared by
// the platform config and fault plan readers. Internal to config/ (toml++ stays inside it).
#pragma once

#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace vbim::config {

toml::table parseTomlDocument(std::string_view text, const std::string& origin);

// The text of a TOML file. `what` names it in errors ("fault plan", "config file"): a missing or
// unreadable path, or a directory where the file was expected, is a ConfigError naming the path.
std::string readTomlFile(const std::string& path, const std::string& what);

}  // namespace vbim::config
