// The exit statuses of every vbim command, in one place: runApp (cli/app.cpp) and the signal
// handling (cli/interrupt.cpp) end with them, and the man page's EXIT STATUS (help/man_page.cpp,
// given them by cli/app_doc.cpp) lists them from here, so the page cannot drift from what the
// program does (docs/cli.md).
#pragma once

#include <csignal>

namespace vbim::cli {

inline constexpr int kExitDone = 0;      // every output is complete
inline constexpr int kExitFailure = 1;   // a failure while running (an output that cannot be written)
inline constexpr int kExitBadInput = 2;  // bad usage or bad input, refused before any work
// `vbim profile --plan --merge` with shards missing or unfinished: each named with how to re-run it
// (docs/sweeps.md), so a batch script can tell "run these shards again" from a bad request.
inline constexpr int kExitShardsMissing = 3;

// The signals that stop a command cleanly (cli/interrupt.hpp), with what the man page calls them.
struct StopSignal {
  int number;
  const char* name;
};
inline constexpr StopSignal kStopSignals[] = {{SIGINT, "SIGINT (Ctrl-C)"}, {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"}};

// 128 + the signal's number: what a shell reports for a process the signal ended, so a script sees
// the same status whether the command cleaned up first (it does) or not.
constexpr int exitForSignal(int signal) {
  return 128 + signal;
}

}  // namespace vbim::cli
