// Ctrl-C (SIGINT), SIGTERM and SIGHUP end a command cleanly: the first one only sets a flag, which
// the long loops look at through checkInterrupted() (every Progress::show calls it), so the command
// stops by throwing cli::Exit(130): the stack unwinds, and each temporary output (OutputDir, the
// stream and image writers' hidden temporary files) is removed on the way out. A second signal
// ends the process at once (the default action is restored after the first).
// Every command catches them, even when started with them ignored (a background job of a script),
// so that Ctrl-C and kill -INT stop author or lightmap as they stop play; vbim installs them before
// it hands a command to vbim-full, so vbim-full never starts with SIGINT ignored, and blocks them
// across the exec, so one that comes while vbim-full loads reaches vbim-full's handler (cli/main.cpp).
// Outputs a killed process could not remove (SIGKILL, a second signal) are removed by the next
// command that writes beside them (streams/temporary_files.hpp).
#pragma once

namespace vbim::cli {

// Installs the handlers (vbim's main first; runApp again, before parsing) and lets through any
// signal that blockInterruptSignals() held back.
void installInterruptHandlers();
// Holds the signals back (they stay pending, and the mask survives exec) while vbim hands a command
// to vbim-full: the exec resets handlers to the default action, which would end vbim-full with no
// message and no clean-up if a Ctrl-C came before its own handlers are in.
void blockInterruptSignals();
// Throws cli::Exit(130, "interrupted ...") once a signal arrived.
void checkInterrupted();

}  // namespace vbim::cli
