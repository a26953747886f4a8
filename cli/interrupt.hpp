// Ctrl-C (SIGINT), SIGTERM and SIGHUP end a command cleanly: the first one only sets a flag, which
// the long loops look at through checkInterrupted() (every Progress::show calls it), so the command
// stops by throwing cli::Exit(130): the stack unwinds, and each temporary output (OutputDir, the
// stream and image writers' hidden temporary files) is removed on the way out. A second signal
// ends the process at once (the default action is restored after the first).
// Every command catches them, even when started with them ignored (a background job of a script),
// so that Ctrl-C and kill -INT stop author or lightmap as they stop play; vbim installs them before
// it hands a command to vbim-full, so vbim-full never starts with SIGINT ignored (cli/main.cpp).
#pragma once

namespace vbim::cli {

// Installs the handlers (vbim's main first; runApp again, before parsing).
void installInterruptHandlers();
// Throws cli::Exit(130, "interrupted ...") once a signal arrived.
void checkInterrupted();

}  // namespace vbim::cli
