#include "cli/command.hpp"

namespace vbim::cli {

void addRender(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render the frames of a play run with OSMesa");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("render", 9); });
}

}  // namespace vbim::cli
