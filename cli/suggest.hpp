// "Did you mean": a mistyped option or command is named, with the closest real name, before any
// other complaint (CLI11 would report a missing --out first when --outt was meant, and its own text
// for an unexpected argument lists the leftovers in reverse order).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// The names of `candidates` a typo of `typed` would most likely come from: those at the smallest
// edit distance (optimal string alignment: inserting, deleting or changing a letter, or swapping two
// neighbours, counts 1), if it is at most a third of the length (at least 1, at most 3); else the
// one name `typed` is a prefix of (3 letters or more). Empty when nothing is close.
std::vector<std::string> closestNames(std::string_view typed, const std::vector<std::string>& candidates);

// " (did you mean 'a'?)" or " (did you mean 'a' or 'b'?)", or "" when `names` is empty.
std::string didYouMean(const std::vector<std::string>& names);

// The first argument of argv (after the subcommand, when argv[1] names one of `app`'s) that CLI11
// would take for an option of the command but which is none of its options, with the message:
// "unknown option '--outt' (did you mean '--out'?)". Values of known options are skipped as CLI11
// takes them (`--seed -1` is a value, checked later), and so is everything after "--".
std::optional<std::string> unknownOption(CLI::App& app, int argc, char** argv);

// The message for a first word that is no command: "unknown command 'pla' (did you mean 'play'?)".
std::string unknownCommand(CLI::App& app, const std::string& typed);

}  // namespace vbim::cli
