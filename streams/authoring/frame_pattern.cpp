#include "streams/authoring/frame_pattern.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "streams/authoring/error.hpp"

namespace vbim::streams {

namespace fs = std::filesystem;

namespace {

struct Field {
  std::string prefix, suffix;
  int width = 0;  // minimum digits (%04d -> 4, %d -> 0)
};

Field parseField(const std::string& name, const std::string& pattern) {
  const std::size_t p = name.find('%');
  if (p == std::string::npos)
    throw AuthoringError("frame pattern '" + pattern + "' has no number field (e.g. %04d) in its file name");
  std::size_t i = p + 1;
  int width = 0;
  if (i < name.size() && name[i] == '0') ++i;
  while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) width = width * 10 + (name[i++] - '0');
  if (i >= name.size() || name[i] != 'd' || width > 9)
    throw AuthoringError("frame pattern '" + pattern + "': the number field must be %d or %0Nd");
  Field f{name.substr(0, p), name.substr(i + 1), width};
  if (f.suffix.find('%') != std::string::npos)
    throw AuthoringError("frame pattern '" + pattern + "' has more than one % field");
  return f;
}

std::string digits(int number, int width) {
  std::string s = std::to_string(number);
  if (static_cast<int>(s.size()) < width) s.insert(0, static_cast<std::size_t>(width) - s.size(), '0');
  return s;
}

}  // namespace

std::string formatFramePattern(const std::string& pattern, int number) {
  const fs::path p(pattern);
  const Field f = parseField(p.filename().string(), pattern);
  return (p.parent_path() / (f.prefix + digits(number, f.width) + f.suffix)).string();
}

std::vector<FrameFile> expandFramePattern(const std::string& pattern) {
  const fs::path p(pattern);
  const Field f = parseField(p.filename().string(), pattern);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw AuthoringError("frame pattern '" + pattern + "': directory " + dir.string() + " does not exist");
  std::map<int, fs::path> found;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= f.prefix.size() + f.suffix.size() || name.compare(0, f.prefix.size(), f.prefix) != 0 ||
        name.compare(name.size() - f.suffix.size(), f.suffix.size(), f.suffix) != 0)
      continue;
    const std::string num = name.substr(f.prefix.size(), name.size() - f.prefix.size() - f.suffix.size());
    if (num.size() > 9 || !std::all_of(num.begin(), num.end(), [](char c) { return std::isdigit(c); })) continue;
    const int n = std::stoi(num);
    if (digits(n, f.width) != num) continue;  // e.g. 00012 does not match %04d
    found[n] = entry.path();
  }
  if (ec) throw AuthoringError("frame pattern '" + pattern + "': cannot list " + dir.string() + ": " + ec.message());
  if (found.empty()) throw AuthoringError("frame pattern '" + pattern + "' matches no file in " + dir.string());
  std::vector<FrameFile> out;
  int expect = found.begin()->first;
  for (const auto& [n, path] : found) {
    if (n != expect) {
      throw AuthoringError("frame pattern '" + pattern + "': " + formatFramePattern(pattern, expect) +
                           " is missing (the sequence runs from " + std::to_string(found.begin()->first) + " to " +
                           std::to_string(found.rbegin()->first) + ")");
    }
    out.push_back(FrameFile{n, path});
    ++expect;
  }
  return out;
}

}  // namespace vbim::streams
