// --threads for the commands that run host threads (play, decode, lightmap), with one meaning and
// one default everywhere (docs/cli.md): N host threads share the work, 1 (the default) keeps it on
// the command's own thread, 0 asks for one per hardware thread of this machine; the bytes out do
// not depend on it. At most what the machine has: more cannot run at once, and a huge count used to
// exhaust the host (issue #16).
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

// Registers --threads on `cmd` into `threads` (set to the default, 1); `what` says what the threads do.
inline CLI::Option* addThreadsOption(CLI::App& cmd, unsigned& threads, const std::string& what) {
  threads = 1;
  static const CLI::Validator zeroIsAll(
      [](std::string& text) {
        if (text == "0") text = std::to_string(hostThreadLimit());
        return std::string();
      },
      "");
  return cmd
      .add_option(
          "--threads", threads,
          what + " (1: the command's own thread; 0: one per hardware thread; the bytes out do not depend on it)")
      ->capture_default_str()
      ->transform(zeroIsAll)
      ->check(hostThreads());
}

}  // namespace vbim::cli
