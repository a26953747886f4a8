#include "config/option_values.hpp"

#include <climits>
#include <map>

#include "config/params_toml.hpp"
#include "gs/params.hpp"
#include "iop/fault_plan.hpp"
#include "runtime/error.hpp"

namespace vbim::config {

Tick parseTime(const std::string& what, const std::string& text) {
  try {
    return iop::parseDuration(text);
  } catch (const std::exception& e) {
    throw Error(what + " '" + text + "': " + e.what() + " (expected a time with a unit, e.g. 12.5s or 800ms)");
  }
}

std::string catchupPolicy(const std::string& name) {
  for (const std::string_view p : gs::kCatchupPolicies) {
    if (p == name) return name;
  }
  throw Error("--policy '" + name + "': expected blend-through, hard-skip or play-late");
}

std::string gsConfigMessage(const gs::GsError& e, const std::string& configPath) {
  if (configPath.empty()) return std::string("the default platform config: ") + e.what();
  std::map<std::string, int> lines;
  try {
    lines = tomlKeyLines(configPath);
  } catch (const ConfigError&) {
    // Already read once without error; if it changed since, the message still names the file.
  }
  const std::string* key = nullptr;
  int line = INT_MAX;
  for (const std::string& k : e.keys()) {
    if (const auto it = lines.find(k); it != lines.end() && it->second < line) {
      key = &k;
      line = it->second;
    }
  }
  if (key == nullptr) return configPath + ": " + e.what();
  return configPath + ":" + std::to_string(line) + ": key '" + *key + "': " + e.what();
}

}  // namespace vbim::config
