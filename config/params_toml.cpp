#include "config/params_toml.hpp"

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "config/toml_document.hpp"

namespace vbim::config {

namespace {

std::string where(const std::string& origin, const toml::source_region& r, const std::string& key) {
  return origin + ":" + std::to_string(r.begin.line) + ": key '" + key + "'";
}

void flatten(const toml::table& t, const std::string& prefix,
             std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [k, v] : t) {
    std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      flatten(*sub, key, out);
    } else {
      out.emplace_back(key, &v);
    }
  }
}

}  // namespace

void applyTomlFile(ParamTable& table, const std::string& path) {
  applyToml(table, readTomlFile(path, "config file"), path);
}

std::map<std::string, int> tomlKeyLines(const std::string& path) {
  const toml::table doc = parseTomlDocument(readTomlFile(path, "config file"), path);
  std::vector<std::pair<std::string, const toml::node*>> entries;
  flatten(doc, "", entries);
  std::map<std::string, int> lines;
  for (const auto& [key, node] : entries) lines[key] = static_cast<int>(node->source().begin.line);
  return lines;
}

void applyToml(ParamTable& table, std::string_view text, const std::string& origin) {
  const toml::table doc = parseTomlDocument(text, origin);
  std::vector<std::pair<std::string, const toml::node*>> entries;
  flatten(doc, "", entries);
  for (const auto& entry : entries) applyTomlValue(table, entry.first, *entry.second, origin);
}

void applyTomlValue(ParamTable& table, const std::string& key, const toml::node& value, const std::string& origin) {
  const toml::node* node = &value;
  const ParamTable::Param* p = table.find(key);
  const std::string at = where(origin, node->source(), key);
  if (p == nullptr) throw ConfigError(at + ": unknown key (see `vbim config --defaults` for the valid keys)");
  std::visit(
      [&](auto* f) {
        using T = std::remove_pointer_t<decltype(f)>;
        if constexpr (std::is_same_v<T, bool>) {
          const auto v = node->value<bool>();
          if (!v) throw ConfigError(at + ": expected true or false");
          *f = *v;
        } else if constexpr (std::is_same_v<T, std::string>) {
          const auto v = node->value<std::string>();
          if (!v) throw ConfigError(at + ": expected a string");
          bool ok = false;
          std::string list;
          for (const auto& c : p->choices) {
            ok = ok || c == *v;
            if (!list.empty()) list += ", ";
            list += c;
          }
          if (!ok) throw ConfigError(at + ": '" + *v + "' is not one of " + list);
          *f = *v;
        } else if constexpr (std::is_same_v<T, double>) {
          if (!node->is_number()) throw ConfigError(at + ": expected a number");
          const double v = *node->value<double>();
          if (!(v >= p->min && v <= p->max)) {
            std::ostringstream m;
            m << at << ": " << v << " is outside the allowed range [" << p->min << ", " << p->max << "] " << p->unit;
            throw ConfigError(m.str());
          }
          *f = v;
        } else {
          if (!node->is_integer()) throw ConfigError(at + ": expected an integer");
          const std::int64_t v = *node->value<std::int64_t>();
          if (static_cast<double>(v) < p->min || static_cast<double>(v) > p->max) {
            std::ostringstream m;
            m << at << ": " << v << " is outside the allowed range [" << static_cast<std::int64_t>(p->min) << ", "
              << static_cast<std::int64_t>(p->max) << "] " << p->unit;
            throw ConfigError(m.str());
          }
          *f = v;
        }
      },
      p->field);
}

}  // namespace vbim::config
