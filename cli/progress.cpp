#include "cli/progress.hpp"

#include "cli/common_options.hpp"
#include "cli/interrupt.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace vbim::cli {

namespace {

constexpr int kBarWidth = 30;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// "8 s", "3 min 20 s", "1 h 05 min".
std::string duration(double seconds) {
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

bool askedInEnvironment() {
  const char* v = std::getenv("VBIM_PROGRESS");
  return v != nullptr && std::string_view(v) == "1";
}

}  // namespace

Progress::Progress(std::string label, std::string unit, bool always)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      terminal_(::isatty(STDERR_FILENO) == 1),
      always_(always || askedInEnvironment() || verbosity() == Verbosity::Verbose),
      never_(verbosity() == Verbosity::Quiet) {}

Progress::~Progress() {
  finish();
}

void Progress::show(double done, double total, std::string_view note) {
  checkInterrupted();  // every long loop passes here: Ctrl-C stops it and unwinds (cli/interrupt.hpp)
  if (never_ || (!terminal_ && !always_)) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last = total > 0 && done >= total;
  if (!terminal_ && !last && lastLog_.time_since_epoch().count() != 0 && now - lastLog_ < std::chrono::seconds(5)) {
    return;
  }
  lastLog_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string line;
  if (total > 0) {
    const double fraction = std::clamp(done / total, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kBarWidth);
    line = label_ + " [" + std::string(static_cast<std::size_t>(filled), '#') +
           std::string(static_cast<std::size_t>(kBarWidth - filled), '.') + "] " + number(done) + "/" + number(total) +
           " " + unit_;
  } else {  // the total is not known in advance: the count alone
    line = label_ + " " + number(done) + " " + unit_;
  }
  if (elapsed > 0.5 && done > 0) {
    const double rate = done / elapsed;
    char text[64];
    std::snprintf(text, sizeof text, "  %.3g %s/s", rate, unit_.c_str());
    line += text;
    if (total > done) line += ", " + duration((total - done) / rate) + " left";
  }
  if (!note.empty()) line += "  " + std::string(note);
  if (!terminal_) {  // a log: whole lines, nothing redrawn
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
    return;
  }
  const std::size_t length = line.size();
  if (length < lastLength_) line.append(lastLength_ - length, ' ');
  lastLength_ = length;
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (!drawn_) return;
  std::fputc('\n', stderr);
  std::fflush(stderr);
  drawn_ = false;
  lastLength_ = 0;
}

}  // namespace vbim::cli
