// vbim: the command-line tool. Thin: parses arguments, wires files to the model.
//
// This program links the model and small libraries only (so `vbim play` stays small and every
// command here starts without loading media libraries); the commands that need OpenImageIO, FFmpeg
// or Mesa, and a `vbim profile` that re-encodes, are run by `vbim-full`, beside this program, with the
// same arguments (see cli/command.hpp).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "cli/command.hpp"
#include "cli/interrupt.hpp"
#include "cli/profile_plan.hpp"

namespace {

// Replaces this process with vbim-full from this program's directory; returns only on failure.
int runFullTool(char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) {
    std::cerr << "vbim: cannot find this program's directory (/proc/self/exe: " << ec.message()
              << "), so cannot run vbim-full for '" << argv[1] << "'\n";
    return 1;
  }
  const std::filesystem::path full = self.parent_path() / "vbim-full";
  vbim::cli::blockInterruptSignals();  // until vbim-full's handlers are in (cli/interrupt.hpp)
  // A signal caught before the block set a flag in this image, which the exec would forget: vbim-full
  // would run the whole command after a Ctrl-C. Nothing is written yet, so stop here.
  try {
    vbim::cli::checkInterrupted();
  } catch (const vbim::cli::Exit& e) {
    std::cerr << "vbim " << argv[1] << ": " << e.what() << "\n";
    return e.code();
  }
  execv(full.c_str(), argv);
  const int err = errno;
  vbim::cli::installInterruptHandlers();
  std::cerr << "vbim: '" << argv[1] << "' is run by vbim-full, expected at " << full.string() << ": "
            << std::strerror(err) << " (build it with scripts/build.sh, or install it beside vbim)\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    // First, and before handing a command to vbim-full: started with SIGINT ignored (a background
    // job of a script), vbim-full would otherwise keep it ignored until its own handler is in, after
    // its libraries have loaded. The exec resets caught signals to their default action, so
    // runFullTool blocks them across it: a Ctrl-C while vbim-full loads waits for its handler.
    vbim::cli::installInterruptHandlers();
    std::vector<char*> args = vbim::cli::helpAsOption(argc, argv);  // `vbim help author` too
    argv = args.data();
    argc = static_cast<int>(args.size()) - 1;
    if (argc > 1) {
      for (const vbim::cli::CommandInfo& c : vbim::cli::kFullOnlyCommands) {
        if (std::string(argv[1]) == c.name) return runFullTool(argv);
      }
    }
    CLI::App app;
    vbim::cli::configureApp(app);
    vbim::cli::addCoreCommands(app);
    vbim::cli::addProfile(app, {});  // no encoder: a profile that re-encodes is handed over below
    // Listed in --help like the others; never parsed here (handed over above).
    for (const vbim::cli::CommandInfo& c : vbim::cli::kFullOnlyCommands)
      app.add_subcommand(c.name, c.summary)->group("Subcommands run by vbim-full");
    try {
      return vbim::cli::runApp(app, argc, argv);
    } catch (const vbim::cli::HandOverToFull&) {
      return runFullTool(argv);  // nothing written yet: vbim-full starts the command again
    }
  } catch (...) {
    std::cerr << "vbim: internal error\n";
    return 1;
  }
}
