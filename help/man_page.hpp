// The man page of vbim (roff, section 1) from its ProgramDoc: every command with its options and
// examples, the exit statuses, the environment, the files (docs/cli.md "Man page and completion").
#pragma once

#include <string>

#include "help/program_doc.hpp"

namespace vbim::help {

std::string manPage(const ProgramDoc& program);

// `s` as roff text: backslashes and hyphens escaped.
std::string roff(const std::string& s);

}  // namespace vbim::help
