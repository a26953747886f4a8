#include "cli/platform_params.hpp"

#include <climits>
#include <map>

#include "cli/command.hpp"
#include "config/params_toml.hpp"
#include "gs/params.hpp"

namespace vbim::cli {

std::string catchupPolicy(const std::string& name) {
  for (const std::string_view p : gs::kCatchupPolicies) {
    if (p == name) return name;
  }
  throw Exit(2, "--policy '" + name + "': expected blend-through, hard-skip or play-late");
}

std::string gsConfigMessage(const gs::GsError& e, const std::string& configPath) {
  if (configPath.empty()) return std::string("the default platform config: ") + e.what();
  std::map<std::string, int> lines;
  try {
    lines = config::tomlKeyLines(configPath);
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

void describePlatform(ParamTable& t, PlatformParams& p) {
  player::describeParams(t, p);
}

void validatePlatform(const PlatformParams& p) {
  player::validate(p);
}

}  // namespace vbim::cli
