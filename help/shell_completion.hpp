// The bash and zsh completions of vbim from its ProgramDoc: the commands, their options, and for an
// option's value its fixed set, a number, a directory or a file.
#pragma once

#include <string>

#include "help/program_doc.hpp"

namespace vbim::help {

std::string bashCompletion(const ProgramDoc& program);
std::string zshCompletion(const ProgramDoc& program);

}  // namespace vbim::help
