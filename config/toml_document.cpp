#include "config/toml_document.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

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

std::string readTomlFile(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ConfigError(path + ": is a directory; expected a " + what + " (a TOML file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open the " + what);
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path + ": cannot read the " + what);
  return text.str();
}

}  // namespace vbim::config
