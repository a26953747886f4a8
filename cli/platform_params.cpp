#include "cli/platform_params.hpp"

#include "cli/command.hpp"
#include "gs/params.hpp"

namespace vbim::cli {

std::string catchupPolicy(const std::string& name) {
  for (const std::string_view p : gs::kCatchupPolicies) {
    if (p == name) return name;
  }
  throw Exit(2, "--policy '" + name + "': expected blend-through, hard-skip or play-late");
}

void describePlatform(ParamTable& t, PlatformParams& p) {
  player::describeParams(t, p);
}

void validatePlatform(const PlatformParams& p) {
  player::validate(p);
}

}  // namespace vbim::cli
