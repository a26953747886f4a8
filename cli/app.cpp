// What both programs share: the app's description, and turning every error into a message and a
// non-zero status.
#include <exception>
#include <iostream>

#include "cli/command.hpp"

namespace vbim::cli {

void configureApp(CLI::App& app) {
  app.description(
      "vbim: a simulator of the PlayStation 2 video-based illumination map pipeline\n"
      "(DVD -> IOP stream ring -> SIF -> EE demux -> IPU decode -> GS blend, on a simulated clock)");
  app.name("vbim");
  app.set_version_flag("--version", "vbim 0.1.0");
  app.require_subcommand(1);
  app.fallthrough(false);
}

void addCoreCommands(CLI::App& app) {
  addPlay(app);
  addInfo(app);
  addDecode(app);
  addConfig(app);
}

int runApp(CLI::App& app, int argc, char** argv) {
  // A first word that is neither an option nor a subcommand gets a plain answer.
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const auto* sub : app.get_subcommands({})) known = known || sub->get_name() == argv[1];
    if (!known) {
      std::cerr << "vbim: unknown subcommand '" << argv[1] << "'\n\n" << app.help();
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) {
      std::cerr << "vbim: " << e.what() << "\n\n" << app.help() << std::flush;
      return 2;
    }
    return app.exit(e);
  } catch (const Exit& e) {
    std::cerr << e.what() << "\n";
    return e.code();
  } catch (const std::exception& e) {
    std::cerr << "vbim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vbim::cli
