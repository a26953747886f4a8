// Test support: how many repetitions a soak test makes.
//
// A soak test repeats one scenario many times at random moments (interrupts, schedules) to reach
// rare interleavings. The Release suite runs the full count. The sanitizer suite runs the same
// code 5-20x slower and looks for memory and undefined-behaviour errors, which the first few
// repetitions already reach, so scripts/test.sh sets VBIM_TEST_SOAK_SCALE there to divide the
// count (see docs/dependencies.md, "CI").
#pragma once

#include <algorithm>
#include <cstdlib>
#include <string>

namespace vbim::testing {

// `full` divided by VBIM_TEST_SOAK_SCALE (a positive integer; unset or invalid means 1), never
// fewer than `atLeast`.
inline int soakRepetitions(int full, int atLeast) {
  int scale = 1;
  if (const char* s = std::getenv("VBIM_TEST_SOAK_SCALE"); s != nullptr) {
    try {
      scale = std::max(1, std::stoi(s));
    } catch (const std::exception&) {
      scale = 1;
    }
  }
  return std::max(atLeast, full / scale);
}

}  // namespace vbim::testing
