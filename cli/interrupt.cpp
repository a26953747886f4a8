#include "cli/interrupt.hpp"

#include <csignal>

#include "cli/command.hpp"

namespace vbim::cli {

namespace {

volatile std::sig_atomic_t gSignal = 0;

extern "C" void onSignal(int sig) {
  gSignal = sig;
  std::signal(sig, SIG_DFL);  // a second one ends the process at once
}

}  // namespace

void installInterruptHandlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, onSignal);
}

void checkInterrupted() {
  if (gSignal != 0) {
    const int sig = gSignal;
    throw Exit(128 + sig, sig == SIGINT ? "interrupted (Ctrl-C); temporary files removed, outputs left as they were"
                                        : "stopped by a signal; temporary files removed, outputs left as they were");
  }
}

}  // namespace vbim::cli
