// --threads for the commands that run host threads (decode, lightmap, author): at most what the
// machine has. More cannot run at once, and a huge count used to exhaust the host (issue #16).
#pragma once

#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/option_checks.hpp"

namespace vbim::cli {

// The hardware threads of this machine (64 when the standard library cannot tell).
inline unsigned hostThreadLimit() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 64u : n;
}

// A validator for a --threads option: a count above hostThreadLimit() is a usage error (exit 2).
inline CLI::Validator hostThreads() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        // The strict reading first (no sign, no wrap, digits only), then the machine's limit.
        if (std::string problem = nonNegativeInteger()(text); !problem.empty()) return problem;
        const unsigned long long n = std::stoull(text);
        const unsigned limit = hostThreadLimit();
        if (n > limit)
          return text + ": this machine has " + std::to_string(limit) + " hardware threads; use at most " +
                 std::to_string(limit);
        return {};
      },
      "at most the machine's hardware threads");
}

}  // namespace vbim::cli
