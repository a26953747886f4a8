#include "runtime/param_table.hpp"

#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

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
