// --threads for the commands that run host threads (decode, lightmap, author): at most what the
// machine has. More cannot run at once, and a huge count used to exhaust the host (issue #16).
#pragma once

#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// The hardware threads of this machine (64 when the standard library cannot tell).
inline unsigned hostThreadLimit() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 64u : n;
}

// A validator for a --threads option: a count above hostThreadLimit() is a usage error (exit 2).
inline CLI::Validator hostThreads() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        unsigned long long n = 0;
        try {
          n = std::stoull(text);
        } catch (const std::exception&) {
          return text + ": expected a whole number of host threads";
        }
        const unsigned limit = hostThreadLimit();
        if (n > limit)
          return text + ": this machine has " + std::to_string(limit) + " hardware threads; use at most " +
                 std::to_string(limit);
        return {};
      },
      "at most the machine's hardware threads");
}

}  // namespace vbim::cli
