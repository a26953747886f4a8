// What a command says on stderr as it runs and when it ends: the words of a long command's progress
// on a terminal or in a log (cli/progress.hpp draws them),
//
//   vbim lightmap [############..................] 48/120 frames  9.6 frames/s, 8 s left  note
//
// and the shorter counts of `vbim profile` ("[3/10, 5 s left] ") and its sweep plans' cases
// ("1h05m left"), and the sizes of the files --verbose lists. Text in, text out: the caller measures
// the host time (never hashed) and prints.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace vbim::help {

// Host seconds left for `total` steps at the rate of `done` in `elapsed` seconds (0 when done is 0).
double secondsLeft(double elapsed, std::size_t done, std::size_t total);

// "8 s", "3 min 20 s", "1 h 05 min".
std::string durationText(double seconds);
// "3m20s", "1h05m".
std::string clockText(double seconds);

// `label` ("vbim play"), a bar of `done` of `total` (whole numbers without decimals; a total of 0:
// not known, the count alone) and `unit` ("frames"), the rate and the time left once `elapsed` is
// over half a second, then `note`.
std::string progressLine(std::string_view label, std::string_view unit, double done, double total, double elapsed,
                         std::string_view note);

// "[3/10, 5 s left] ": step `done` of `total`, `left` seconds to go.
std::string countText(std::size_t done, std::size_t total, double left);

// A file's size as --verbose lists the files written: "812 bytes", "12.3 kB" (decimal units, as
// `ls -h --si`).
std::string sizeText(std::uintmax_t bytes);

}  // namespace vbim::help
