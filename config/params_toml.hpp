// TOML documents applied to a ParamTable: the one place that turns a platform config, a lighting
// config or any other `[section] key = value` file into the model's plain parameter structs. Unknown
// keys, wrong types and out-of-range values are rejected with the file, the line and the key.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "runtime/param_table.hpp"

namespace vbim::config {

// Applies a TOML document to the fields bound in `table`. `origin` names it in errors (a path or
// "<string>"). Throws ConfigError.
void applyToml(ParamTable& table, std::string_view text, const std::string& origin);
// Reads `path` and applies it; a missing or unreadable file is a ConfigError naming it.
void applyTomlFile(ParamTable& table, const std::string& path);
// The line each dotted key is set on in the TOML file `path` ("gs.strip_rows" -> 3), so a check
// made after loading (the GS's VRAM layout, ...) can point at `file:line: key`. Throws ConfigError.
std::map<std::string, int> tomlKeyLines(const std::string& path);

}  // namespace vbim::config
