// The man page and the bash and zsh completions of vbim, generated from the same option
// definitions as --help (the CLI::App tree of vbim-full, which has every command), so they cannot
// drift from the program: `vbim-full --generate man|bash|zsh FILE` (hidden; run at build time by
// cli/CMakeLists.txt and installed by `cmake --install`, docs/cli.md "Man page and completion").
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// The document of kind "man" (roff, section 1), "bash" or "zsh" for `app` (configured and with
// every command added, as runApp parses it). Throws Exit(2) for another kind.
std::string generateDocs(CLI::App& app, const std::string& kind);

// `vbim-full --generate KIND [FILE]`: prepares `app` (prepareApp), writes the document to FILE (or
// stdout); the exit status.
int runGenerate(CLI::App& app, const std::string& kind, const std::string& file);

}  // namespace vbim::cli
