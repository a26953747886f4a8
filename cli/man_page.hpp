// The man page of vbim (roff, section 1), from the same option definitions as --help
// (cli/generate_docs.hpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

std::string manPage(CLI::App& app);

}  // namespace vbim::cli
