// The CLI::App tree as --help shows it, walked by the man page and the shell completions
// (cli/generate_docs.hpp): the commands, their named options, and what each option is called.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// The commands as --help lists them (named, not the program's own help).
inline std::vector<CLI::App*> listedCommands(CLI::App& app) {
  std::vector<CLI::App*> out;
  for (CLI::App* sub : app.get_subcommands({})) {
    if (!sub->get_name().empty()) out.push_back(sub);
  }
  return out;
}

// Options with a name (-o, --out), in the order --help lists them.
inline std::vector<const CLI::Option*> namedOptions(const CLI::App& cmd) {
  std::vector<const CLI::Option*> out;
  for (const CLI::Option* opt : cmd.get_options({})) {
    if (opt->nonpositional()) out.push_back(opt);
  }
  return out;
}

inline std::vector<std::string> optionNames(const CLI::Option& opt) {
  std::vector<std::string> names;
  for (const std::string& s : opt.get_snames()) names.push_back("-" + s);
  for (const std::string& l : opt.get_lnames()) names.push_back("--" + l);
  return names;
}

// A flag takes none: CLI11 gives it a type size of 1 like any option, and expects no item.
inline bool takesValue(const CLI::Option& opt) {
  return opt.get_expected_max() > 0;
}

// The first line of a description (--help may wrap a summary; a man page and a menu want one line).
inline std::string firstLine(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

}  // namespace vbim::cli
