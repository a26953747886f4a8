#include "runtime/params.hpp"

#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

#include <toml++/toml.h>

namespace vbim {

namespace {

std::string valueText(const ParamTable::Param& p) {
  std::ostringstream s;
  std::visit(
      [&](auto* f) {
        using T = std::remove_pointer_t<decltype(f)>;
        if constexpr (std::is_same_v<T, bool>) {
          s << (*f ? "true" : "false");
        } else if constexpr (std::is_same_v<T, std::string>) {
          s << '"' << *f << '"';
        } else if constexpr (std::is_same_v<T, double>) {
          s.precision(17);
          s << *f;
          if (s.str().find_first_of(".e") == std::string::npos) s << ".0";
        } else {
          s << *f;
        }
      },
      p.field);
  return s.str();
}

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

void ParamTable::addInt(std::string key, std::int64_t* field, std::int64_t min, std::int64_t max, std::string unit,
                        std::string source) {
  params_.push_back(Param{std::move(key),
                          std::move(unit),
                          std::move(source),
                          field,
                          static_cast<double>(min),
                          static_cast<double>(max),
                          {}});
}
void ParamTable::addReal(std::string key, double* field, double min, double max, std::string unit, std::string source) {
  params_.push_back(Param{std::move(key), std::move(unit), std::move(source), field, min, max, {}});
}
void ParamTable::addBool(std::string key, bool* field, std::string source) {
  params_.push_back(Param{std::move(key), "", std::move(source), field, 0, 1, {}});
}
void ParamTable::addChoice(std::string key, std::string* field, std::vector<std::string> choices, std::string source) {
  params_.push_back(Param{std::move(key), "", std::move(source), field, 0, 0, std::move(choices)});
}

const ParamTable::Param* ParamTable::find(std::string_view key) const {
  for (const auto& p : params_) {
    if (p.key == key) return &p;
  }
  return nullptr;
}

void ParamTable::loadTomlFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open the platform config");
  std::stringstream ss;
  ss << in.rdbuf();
  loadToml(ss.str(), path);
}

void ParamTable::loadToml(std::string_view text, const std::string& origin) {
  toml::table doc;
  try {
    doc = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw ConfigError(origin + ":" + std::to_string(e.source().begin.line) +
                      ": TOML syntax error: " + std::string(e.description()));
  }
  std::vector<std::pair<std::string, const toml::node*>> entries;
  flatten(doc, "", entries);
  for (const auto& entry : entries) {
    const std::string& key = entry.first;
    const toml::node* node = entry.second;
    const Param* p = find(key);
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
}

void ParamTable::writeToml(std::ostream& out) const {
  // Group by the first key component, as TOML tables.
  std::map<std::string, std::vector<const Param*>> groups;
  std::vector<std::string> order;
  for (const auto& p : params_) {
    const auto dot = p.key.find('.');
    const std::string g = dot == std::string::npos ? "" : p.key.substr(0, dot);
    if (!groups.count(g)) order.push_back(g);
    groups[g].push_back(&p);
  }
  bool firstGroup = true;
  for (const auto& g : order) {
    if (!firstGroup) out << "\n";
    firstGroup = false;
    if (!g.empty()) out << "[" << g << "]\n";
    for (const Param* p : groups[g]) {
      const std::string local = g.empty() ? p->key : p->key.substr(g.size() + 1);
      out << "# " << p->source;
      if (!p->unit.empty()) out << " [" << p->unit << "]";
      out << "\n" << local << " = " << valueText(*p) << "\n";
    }
  }
}

void ParamTable::writeMarkdown(std::ostream& out) const {
  out << "| key | default | unit | source |\n|---|---|---|---|\n";
  for (const auto& p : params_) {
    out << "| `" << p.key << "` | " << valueText(p) << " | " << p.unit << " | " << p.source << " |\n";
  }
}

}  // namespace vbim
