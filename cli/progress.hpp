// The one progress line of the long commands (play, render, lightmap, author, decode, profile):
//
//   vbim lightmap [############..................] 48/120 frames  9.6 frames/s, 8 s left  note
//
// redrawn in place ("\r") on stderr, and only when stderr is a terminal, so logs, pipes and tests
// stay clean; finished with a newline. Asked for explicitly (`always`, or VBIM_PROGRESS=1 in the
// environment), it also writes to a non-terminal: whole lines, at most one every 5 s (a batch
// job's log), as under --verbose; --quiet draws nothing. Rate and time left come from the host's clock: shown to the
// user, never hashed. The words are help::progressLine's (help/status_text.hpp). Libraries never print: they report
// through a plain callback (render::RenderProgressFn, lighting::TechniqueAProgressFn) that the command forwards here.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace vbim::cli {

class Progress {
 public:
  // `label` starts the line (the command, "vbim play"); `unit` follows the count ("frames", "s").
  Progress(std::string label, std::string unit, bool always = false);
  // Ends the line if one was drawn, so a message after an error starts on a line of its own.
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Redraws the line: `done` of `total` (whole numbers print without decimals; a total of 0: not
  // known, the count alone), then `note`.
  void show(double done, double total, std::string_view note = {});
  // Ends the line (once).
  void finish();

 private:
  std::string label_;
  std::string unit_;
  bool terminal_;
  bool always_;
  bool never_;  // --quiet (cli/common_options.hpp)
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastLog_{};
  std::size_t lastLength_ = 0;  // to blank what a longer previous line left behind
};

}  // namespace vbim::cli
