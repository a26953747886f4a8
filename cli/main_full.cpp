// vbim-full: every vbim command, including those that author, render and plot (OpenImageIO,
// FFmpeg, Mesa). Users normally reach it through `vbim`, which hands these commands over.
#include <iostream>
#include <string_view>

#include "cli/command.hpp"
#include "cli/generate_docs.hpp"
#include "cli/profile_plan.hpp"
#include "sweep/outputs/reencoded_streams.hpp"

int main(int argc, char** argv) {
  try {
    CLI::App app;
    vbim::cli::configureApp(app);
    vbim::cli::addDemo(app);
    vbim::cli::addCoreCommands(app);
    vbim::cli::addProfile(app, {&vbim::sweep::reencodedStreams, &vbim::sweep::transcodePlanStream});
    vbim::cli::addAuthor(app);
    vbim::cli::addLightmap(app);
    vbim::cli::addRender(app);
    // Hidden: the man page and completions from these definitions (built by cli/CMakeLists.txt).
    if (argc >= 3 && argc <= 4 && std::string_view(argv[1]) == "--generate")
      return vbim::cli::runGenerate(app, argv[2], argc == 4 ? argv[3] : "");
    return vbim::cli::runApp(app, argc, argv);
  } catch (...) {
    std::cerr << "vbim: internal error\n";
    return 1;
  }
}
