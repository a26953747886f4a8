// vbim-full: every vbim command, including those that author, render and plot (OpenImageIO,
// FFmpeg, Mesa). Users normally reach it through `vbim`, which hands these commands over.
#include <iostream>

#include "cli/command.hpp"

int main(int argc, char** argv) {
  try {
    CLI::App app;
    vbim::cli::configureApp(app);
    vbim::cli::addDemo(app);
    vbim::cli::addCoreCommands(app);
    vbim::cli::addProfile(app);
    vbim::cli::addAuthor(app);
    vbim::cli::addLightmap(app);
    vbim::cli::addRender(app);
    return vbim::cli::runApp(app, argc, argv);
  } catch (...) {
    std::cerr << "vbim: internal error\n";
    return 1;
  }
}
