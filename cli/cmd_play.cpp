#include "cli/command.hpp"

namespace vbim::cli {

void addPlay(CLI::App& app) {
  auto* cmd = app.add_subcommand("play", "Play a VBIM disc through the whole pipeline on the simulated clock");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("play", 7); });
}

}  // namespace vbim::cli
