#include "help/status_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace vbim::help {

namespace {

constexpr int kBarWidth = 30;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

double secondsLeft(double elapsed, std::size_t done, std::size_t total) {
  if (done == 0) return 0;
  return elapsed / static_cast<double>(done) * static_cast<double>(total - std::min(done, total));
}

std::string durationText(double seconds) {
  const long long s = std::llround(seconds);
  char text[48];
  if (s < 60) {
    std::snprintf(text, sizeof text, "%lld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%lld min %02lld s", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld h %02lld min", s / 3600, (s % 3600) / 60);
  }
  return text;
}

std::string clockText(double seconds) {
  const long long s = std::llround(seconds);
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, s / 60 % 60);
  } else {
    std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
  }
  return text;
}

std::string progressLine(std::string_view label, std::string_view unit, double done, double total, double elapsed,
                         std::string_view note) {
  std::string line(label);
  if (total > 0) {
    const double fraction = std::clamp(done / total, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kBarWidth);
    line += " [" + std::string(static_cast<std::size_t>(filled), '#') +
            std::string(static_cast<std::size_t>(kBarWidth - filled), '.') + "] " + number(done) + "/" + number(total);
  } else {  // the total is not known in advance: the count alone
    line += " " + number(done);
  }
  line += " ";
  line += unit;
  if (elapsed > 0.5 && done > 0) {
    const double rate = done / elapsed;
    char text[64];
    std::snprintf(text, sizeof text, "  %.3g %.*s/s", rate, static_cast<int>(unit.size()), unit.data());
    line += text;
    if (total > done) line += ", " + durationText((total - done) / rate) + " left";
  }
  if (!note.empty()) {
    line += "  ";
    line += note;
  }
  return line;
}

std::string countText(std::size_t done, std::size_t total, double left) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", left);
  return "[" + std::to_string(done) + "/" + std::to_string(total) + ", " + text + " s left] ";
}

std::string sizeText(std::uintmax_t bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB"};
  double v = static_cast<double>(bytes);
  std::size_t u = 0;
  while (v >= 1000 && u + 1 < std::size(units)) {
    v /= 1000;
    ++u;
  }
  char text[32];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
  return text;
}

}  // namespace vbim::help
