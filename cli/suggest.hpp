// "Did you mean": a mistyped option or command is named, with the closest real name, before any
// other complaint (CLI11 would report a missing --out first when --outt was meant, and its own text
// for an unexpected argument lists the leftovers in reverse order). The closest names are
// help::closestNames (help/did_you_mean.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// The first argument of argv (after the subcommand, when argv[1] names one of `app`'s) that CLI11
// would take for an option of the command but which is none of its options, with the message:
// "unknown option '--outt' (did you mean '--out'?)". Values of known options are skipped as CLI11
// takes them (`--seed -1` is a value, checked later), and so is everything after "--".
std::optional<std::string> unknownOption(CLI::App& app, int argc, char** argv);

// The subcommand of `app` called `name` (the first argument, say), or nullptr.
CLI::App* subcommandNamed(CLI::App& app, std::string_view name);

// The message for a first word that is no command: "unknown command 'pla' (did you mean 'play'?)".
std::string unknownCommand(CLI::App& app, const std::string& typed);

}  // namespace vbim::cli
