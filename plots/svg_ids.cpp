#include "plots/svg_ids.hpp"

#include <cctype>
#include <map>

namespace vbim::plots {

std::string renumberCairoIds(std::string_view svg) {
  static constexpr std::string_view kPrefixes[] = {"surface", "image"};
  std::map<std::string, std::map<std::string, int, std::less<>>, std::less<>> numbers;  // prefix -> old -> new
  std::string out;
  out.reserve(svg.size());
  std::size_t i = 0;
  while (i < svg.size()) {
    const char c = svg[i];
    out += c;
    ++i;
    if (c != '"' && c != '#') continue;
    for (std::string_view prefix : kPrefixes) {
      if (svg.substr(i, prefix.size()) != prefix) continue;
      std::size_t end = i + prefix.size();
      while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
      if (end == i + prefix.size()) continue;  // no number: not one of cairo's ids
      auto& table = numbers[std::string(prefix)];
      const std::string old(svg.substr(i + prefix.size(), end - i - prefix.size()));
      const auto [it, added] = table.try_emplace(old, static_cast<int>(table.size()) + 1);
      out.append(prefix);
      out += std::to_string(it->second);
      i = end;
      break;
    }
  }
  return out;
}

}  // namespace vbim::plots
