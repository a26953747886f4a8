#include "cli/platform_params.hpp"

namespace vbim::cli {

void describePlatform(ParamTable& t, PlatformParams& p) {
  player::describeParams(t, p);
}

void validatePlatform(const PlatformParams& p) {
  player::validate(p);
}

}  // namespace vbim::cli
