#include "cli/command.hpp"

namespace vbim::cli {

void addInfo(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Inspect a VBIM stream: streams, frames, sectors per frame, bitrate, descriptor");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("info", 4); });
}

}  // namespace vbim::cli
