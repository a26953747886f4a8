#include "help/option_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <system_error>
#include <type_traits>

#include "help/did_you_mean.hpp"

namespace vbim::help {

namespace {

std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

template <typename T>
std::string integerProblem(const std::string& text) {
  if (text.empty()) return "expected a whole number, found nothing";
  if constexpr (std::is_unsigned_v<T>) {
    if (text.front() == '-') return quoted(text) + " is negative; expected a whole number 0 or more";
  }
  T value{};
  const char* end = text.data() + text.size();
  const char* first = text.data() + (text.front() == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, end, value);
  if (ec == std::errc::result_out_of_range) {
    return quoted(text) + " is out of range (at most " + std::to_string(std::numeric_limits<T>::max()) + ")";
  }
  if (ec != std::errc() || ptr != end) return quoted(text) + " is not a whole number";
  return {};
}

}  // namespace

std::string wholeNumberProblem(const std::string& text, bool negativeAllowed) {
  return negativeAllowed ? integerProblem<std::int64_t>(text) : integerProblem<std::uint64_t>(text);
}

std::string numberProblem(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec == std::errc::result_out_of_range) return quoted(text) + " is out of range";
  if (ec != std::errc() || ptr != end) return quoted(text) + " is not a number";
  if (!std::isfinite(value)) return quoted(text) + " is not a finite number";
  return {};
}

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
