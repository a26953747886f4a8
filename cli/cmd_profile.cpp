#include "cli/command.hpp"

namespace vbim::cli {

void addProfile(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("profile", "Sweep ring size, bitrate, faults and policy; find the longest survivable stall");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("profile", 7); });
}

}  // namespace vbim::cli
