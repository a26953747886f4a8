#include "cli/command.hpp"

namespace vbim::cli {

void addDecode(CLI::App& app) {
  auto* cmd = app.add_subcommand("decode", "Decode every picture of a stream with the IPU model (no timing)");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("decode", 5); });
}

}  // namespace vbim::cli
