#include "help/option_text.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "help/did_you_mean.hpp"

namespace vbim::help {

std::vector<std::string> choicesIn(const std::string& description) {
  const auto open = description.find('{');
  const auto close = description.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  std::vector<std::string> out;
  std::istringstream items(description.substr(open + 1, close - open - 1));
  for (std::string item; std::getline(items, item, ',');) {
    item = item.substr(0, item.find("->"));
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::string plainTypeText(const std::string& opts, const std::string& typeName) {
  std::string s = opts;
  const auto colon = typeName.find(':');
  const auto at = s.find(typeName);
  if (colon == std::string::npos || at == std::string::npos) return s;
  const std::string base = typeName.substr(0, colon);
  std::string kept;  // descriptions that say something: a range, a limit
  std::istringstream parts(typeName.substr(colon + 1));
  for (std::string part; std::getline(parts, part, ':');) {
    if (part.rfind(base + " ", 0) == 0) part.erase(0, base.size() + 1);  // "INT in [0 - 511]"
    const bool bareName = std::none_of(part.begin(), part.end(), [](unsigned char c) { return std::islower(c); });
    if (!bareName) kept += (kept.empty() ? "" : ", ") + part;
  }
  s.erase(at + colon, typeName.size() - colon);
  if (!kept.empty()) {
    std::size_t end = at + colon;  // after "=DEFAULT" when there is one
    if (end < s.size() && s[end] == '=') end = std::min(s.find(' ', end), s.size());
    s.insert(end, " (" + kept + ")");
  }
  return s;
}

std::string unknownName(const std::string& what, const std::string& typed, const std::vector<std::string>& names) {
  return "unknown " + what + " '" + typed + "'" + didYouMean(closestNames(typed, names));
}

}  // namespace vbim::help
