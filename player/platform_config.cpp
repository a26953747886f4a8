#include "player/platform_config.hpp"

namespace vbim::player {

void describeParams(ParamTable& t, PlatformConfig& p) {
  iop::describeParams(t, p.iop);
  ipu::describeParams(t, p.ipu);
  gs::describeParams(t, p.gs);
  describeParams(t, p.ee);
}

void validate(const PlatformConfig& p) {
  iop::validate(p.iop);
}

}  // namespace vbim::player
