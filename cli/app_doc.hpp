// The CLI::App tree as --help shows it, read into the plain description the man page and the shell
// completions are written from (help/program_doc.hpp; cli/generate_docs.hpp): the commands, their
// options, what each option's value is, and the exit statuses (cli/exit_status.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include "help/program_doc.hpp"

namespace vbim::cli {

// `app` configured and with every command added, as runApp parses it.
help::ProgramDoc programDoc(CLI::App& app);

}  // namespace vbim::cli
