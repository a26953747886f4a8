// A command-line program as its documents describe it: its commands, their options and what each
// option's value is, in plain structs. The man page and the shell completions (man_page.hpp,
// shell_completion.hpp) are written from one; vbim's is read from the options --help shows
// (cli/app_doc.hpp), so no document can drift from the program.
#pragma once

#include <string>
#include <vector>

namespace vbim::help {

// What a shell offers for an option's value.
enum class ValueKind { None, Choice, Number, Directory, File };  // None: a flag, no value

struct OptionDoc {
  std::vector<std::string> names;  // "-o", "--out"; a positional's one name ("stream")
  bool positional = false;
  bool many = false;        // a positional that takes several values
  std::string valueText;    // a named option's value as --help shows it ("TEXT=png"), or empty
  std::string description;  // may span lines
  ValueKind value = ValueKind::File;
  std::vector<std::string> choices;  // ValueKind::Choice: the fixed set
  bool list = false;                 // comma-separated values (--policy a,b)
};

struct CommandDoc {
  std::string name;
  std::string description;         // the first line is its summary
  std::string footer;              // examples, as --help ends with them
  std::vector<OptionDoc> options;  // in the order --help lists them, positionals included
};

// How a program ends (the man page's EXIT STATUS).
struct ExitDoc {
  int done = 0;
  int failure = 1;
  int badInput = 2;
  int shardsMissing = 3;  // a sweep's --merge with shards to re-run
  struct Signal {
    std::string name;  // "SIGINT (Ctrl-C)"
    int status;        // what the program exits with when the signal stops it
  };
  std::vector<Signal> signals;
};

struct ProgramDoc {
  std::string version;
  std::string description;
  std::string footer;
  std::vector<OptionDoc> options;  // the program's own (--help, --version): named ones only
  std::vector<CommandDoc> commands;
  ExitDoc exits;
};

}  // namespace vbim::help
