#include "cli/command.hpp"

namespace vbim::cli {

void addConfig(CLI::App& app) {
  auto* cmd = app.add_subcommand("config", "Print or check a platform config (every timing constant, with sources)");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("config", 3); });
}

}  // namespace vbim::cli
