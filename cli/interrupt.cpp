#include "cli/interrupt.hpp"

#include <signal.h>

#include <csignal>

#include "cli/command.hpp"
#include "cli/exit_status.hpp"

namespace vbim::cli {

namespace {

volatile std::sig_atomic_t gSignal = 0;

extern "C" void onSignal(int sig) {
  gSignal = sig;
  std::signal(sig, SIG_DFL);  // a second one ends the process at once
}

void setMask(int how) {
  sigset_t set;
  sigemptyset(&set);
  for (const StopSignal& s : kStopSignals) sigaddset(&set, s.number);
  sigprocmask(how, &set, nullptr);
}

}  // namespace

void installInterruptHandlers() {
  for (const StopSignal& s : kStopSignals) std::signal(s.number, onSignal);
  // Signals held back by blockInterruptSignals() (across the exec into vbim-full) arrive now, at
  // the handler.
  setMask(SIG_UNBLOCK);
}

void blockInterruptSignals() {
  setMask(SIG_BLOCK);
}

void checkInterrupted() {
  if (gSignal != 0) {
    const int sig = gSignal;
    throw Exit(exitForSignal(sig), sig == SIGINT
                                       ? "interrupted (Ctrl-C); temporary files removed, outputs left as they were"
                                       : "stopped by a signal; temporary files removed, outputs left as they were");
  }
}

}  // namespace vbim::cli
