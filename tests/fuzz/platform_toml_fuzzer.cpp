// libFuzzer target: the platform-config TOML reader on any text. It must accept it or throw a
// vbim::Error (a message naming the place); any other exception, a crash or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "config/platform_config_toml.hpp"
#include "runtime/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)vbim::config::loadPlatformToml(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
  } catch (const vbim::Error&) {
  }
  return 0;
}
