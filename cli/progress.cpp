#include "cli/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <utility>

#include "cli/common_options.hpp"
#include "cli/interrupt.hpp"
#include "help/status_text.hpp"

namespace vbim::cli {

namespace {

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
  std::string line = help::progressLine(label_, unit_, done, total, elapsed, note);
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
