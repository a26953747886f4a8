// Named, documented, range-checked parameters: every timing constant of the model is one of these,
// bound to a field of a component's plain settings struct. A platform config (TOML, read by
// config/params_toml.hpp) sets them by dotted key ("drive.full_seek_ms"); unknown keys and
// out-of-range values are rejected with the file, line and key. The same table prints the defaults
// and their sources for docs/.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "runtime/error.hpp"

namespace vbim {

class ParamTable {
 public:
  struct Param {
    std::string key;     // "drive.full_seek_ms"
    std::string unit;    // "ms", "sectors", "bytes/s", ...
    std::string source;  // where the default comes from, or "assumption: why"
    std::variant<std::int64_t*, double*, bool*, std::string*> field;
    double min = 0;
    double max = 0;
    std::vector<std::string> choices;  // for string parameters
  };

  void addInt(std::string key, std::int64_t* field, std::int64_t min, std::int64_t max, std::string unit,
              std::string source);
  void addReal(std::string key, double* field, double min, double max, std::string unit, std::string source);
  void addBool(std::string key, bool* field, std::string source);
  void addChoice(std::string key, std::string* field, std::vector<std::string> choices, std::string source);

  const std::vector<Param>& params() const { return params_; }
  const Param* find(std::string_view key) const;

  // Writes every parameter with its current value as a commented TOML file.
  void writeToml(std::ostream& out) const;
  // Writes a Markdown table: key, default, unit, source.
  void writeMarkdown(std::ostream& out) const;

 private:
  std::vector<Param> params_;
};

}  // namespace vbim
