// The bash and zsh completions of vbim, from the same option definitions as --help
// (cli/generate_docs.hpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

std::string bashCompletion(CLI::App& app);
std::string zshCompletion(CLI::App& app);

}  // namespace vbim::cli
