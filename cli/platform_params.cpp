#include "cli/platform_params.hpp"

namespace vbim::cli {

void describePlatform(ParamTable& t, PlatformParams& p) {
  iop::describeParams(t, p.iop);
}

void validatePlatform(const PlatformParams& p) {
  iop::validate(p.iop);
}

}  // namespace vbim::cli
