// The options every command that writes files shares, added in one place (runApp) so they mean the
// same everywhere (docs/cli.md, "Options every command shares"):
//   -o, --out DIR   where the outputs go: each command registers it as "-o,--out" (its help text
//                   differs); addCommonOptions refuses to start if one does not (a programming error);
//   -q, --quiet     no progress and no summary on stdout: only warnings and errors (stderr), and
//                   what was asked for by name (--json);
//   -v, --verbose   progress lines even when stderr is not a terminal (at most one every 5 s, as
//                   VBIM_PROGRESS=1), and at the end every file written, with its size (on stderr: stdout keeps
//                   the summary, or the --json document, alone).
// The commands that write files are those with --out; the others (info, config) print what they
// were asked for, which --quiet would hide.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vbim::cli {

enum class Verbosity { Quiet, Normal, Verbose };

// Adds -q/--quiet and -v/--verbose to every subcommand of `app` that has --out.
void addCommonOptions(CLI::App& app);

// What --quiet / --verbose asked for (Normal by default).
Verbosity verbosity();

// The program's standard output even under --quiet (which silences std::cout): for output the user
// asked for by name, such as a --json summary.
std::ostream& requestedOut();

// A value from a fixed set, for an option named `option` ("--format"): --help shows the set
// ({png,exr}) and the shell completions offer it (cli/app_doc.cpp reads the same
// description, as it reads CLI::IsMember's); another value is bad input, refused before any work
// with the message the command's own check gives: "--format 'gif': expected png or exr".
CLI::Validator oneOf(const std::string& option, std::vector<std::string> values);
// --policy: one of gs::kCatchupPolicies (play, replay; profile's list, each item).
CLI::Validator catchupPolicy();

// --png-level (play, decode): zlib's level for the PNG pictures a command writes, the same words and
// default everywhere. The run checks the range (its message names the option and the range).
CLI::Option* addPngLevelOption(CLI::App& cmd, int& level);

// Under --verbose, after a command that wrote `out` (a directory or a file) finished: one line per
// file written, with its size, on stderr. Nothing otherwise.
void listWritten(const CLI::App& command);

}  // namespace vbim::cli
