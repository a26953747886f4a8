#include "config/toml_document.hpp"

#include "runtime/error.hpp"

namespace vbim::config {

toml::table parseTomlDocument(std::string_view text, const std::string& origin) {
  try {
    return toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw ConfigError(origin + ":" + std::to_string(e.source().begin.line) +
                      ": TOML syntax error: " + std::string(e.description()));
  }
}

}  // namespace vbim::config
