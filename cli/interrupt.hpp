// Ctrl-C (SIGINT), SIGTERM and SIGHUP end a command cleanly: the first one only sets a flag, which
// the long loops look at through checkInterrupted() (every Progress::show calls it), so the command
// stops by throwing cli::Exit(130): the stack unwinds, and each temporary output (OutputDir, the
// stream and image writers' hidden temporary files) is removed on the way out. A second signal
// ends the process at once (the default action is restored after the first).
#pragma once

namespace vbim::cli {

// Installs the handlers (runApp does, before parsing).
void installInterruptHandlers();
// Throws cli::Exit(130, "interrupted ...") once a signal arrived.
void checkInterrupted();

}  // namespace vbim::cli
