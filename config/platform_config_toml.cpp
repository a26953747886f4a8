#include "config/platform_config_toml.hpp"

#include "config/params_toml.hpp"

namespace vbim::config {

player::PlatformConfig loadPlatformToml(std::string_view text, const std::string& origin) {
  player::PlatformConfig c;
  ParamTable t;
  player::describeParams(t, c);
  applyToml(t, text, origin);
  player::validate(c);
  return c;
}

player::PlatformConfig loadPlatformFile(const std::string& path) {
  player::PlatformConfig c;
  ParamTable t;
  player::describeParams(t, c);
  applyTomlFile(t, path);
  player::validate(c);
  return c;
}

}  // namespace vbim::config
