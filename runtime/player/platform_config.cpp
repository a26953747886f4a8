#include "runtime/player/platform_config.hpp"

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

PlatformConfig loadPlatformToml(std::string_view text, const std::string& origin) {
  PlatformConfig c;
  ParamTable t;
  describeParams(t, c);
  t.loadToml(text, origin);
  validate(c);
  return c;
}

PlatformConfig loadPlatformFile(const std::string& path) {
  PlatformConfig c;
  ParamTable t;
  describeParams(t, c);
  t.loadTomlFile(path);
  validate(c);
  return c;
}

}  // namespace vbim::player
