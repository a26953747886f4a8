#include "cli/command.hpp"

namespace vbim::cli {

void addAuthor(CLI::App& app) {
  auto* cmd = app.add_subcommand("author", "Author a VBIM stream (MPEG-2 PS, 2048-byte packs) from image sequences");
  cmd->allow_extras();
  cmd->callback([] { notYetAvailable("author", 4); });
}

}  // namespace vbim::cli
