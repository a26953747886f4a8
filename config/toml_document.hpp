// One TOML document parsed, with syntax errors as ConfigError naming the file and line: shared by
// the platform config and fault plan readers. Internal to config/ (toml++ stays inside it).
#pragma once

#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "runtime/param_table.hpp"

namespace vbim::config {

toml::table parseTomlDocument(std::string_view text, const std::string& origin);

// The text of a TOML file. `what` names it in errors ("fault plan", "config file"): a missing or
// unreadable path, or a directory where the file was expected, is a ConfigError naming the path.
std::string readTomlFile(const std::string& path, const std::string& what);

// Sets the parameter `key` of `table` from `value` (type and range checked; errors name
// origin:line: key 'key'). The step applyToml takes for each key of a document.
void applyTomlValue(ParamTable& table, const std::string& key, const toml::node& value, const std::string& origin);

}  // namespace vbim::config
