#include "cli/command.hpp"

namespace vbim::cli {

void addLightmap(CLI::App& app) {
  auto* cmd = app.add_subcommand("lightmap", "Generate day/night terrain lightmaps with Technique A");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("lightmap", 8); });
}

}  // namespace vbim::cli
