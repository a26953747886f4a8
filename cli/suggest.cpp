#include "cli/suggest.hpp"

#include <algorithm>
#include <cstddef>

#include "help/option_text.hpp"

namespace vbim::cli {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// As CLI11's detail::split_long / split_short tell options from values (CLI/Split.hpp).
bool looksLong(const std::string& s) {
  return s.size() > 2 && s.compare(0, 2, "--") == 0 && CLI::detail::valid_first_char(s[2]);
}
bool looksShort(const std::string& s) {
  return s.size() > 1 && s[0] == '-' && s[1] != '-' && CLI::detail::valid_first_char(s[1]);
}

// Every long name of `app`'s options ("--out") and the subcommands' names, for suggestions.
std::vector<std::string> longNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options({})) {
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
  }
  return names;
}

CLI::Option* findLong(CLI::App& app, const std::string& name) {
  for (CLI::Option* opt : app.get_options({})) {
    if (opt->check_lname(name)) return opt;
  }
  return nullptr;
}

CLI::Option* findShort(CLI::App& app, const std::string& name) {
  for (CLI::Option* opt : app.get_options({})) {
    if (opt->check_sname(name)) return opt;
  }
  return nullptr;
}

// How many of the following arguments `opt` takes whatever they look like (CLI11's minimum).
std::size_t valuesTaken(const CLI::Option& opt) {
  const int n = std::min(opt.get_type_size_min(), opt.get_items_expected_min());
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

std::string unknownMessage(const CLI::App& app, const std::string& token) {
  const std::string name = token.substr(0, token.find('='));
  // Only a long name is offered the closest ones: a single letter is close to every other.
  return help::unknownName("option", name, name.rfind("--", 0) == 0 ? longNames(app) : std::vector<std::string>{});
}

// Scans args[from, to) against `app`'s options; the first unknown one's message.
std::optional<std::string> scan(CLI::App& app, const std::vector<std::string>& args, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i) {
    const std::string& a = args[i];
    if (a == "--") return std::nullopt;  // the rest are positionals
    CLI::Option* opt = nullptr;
    bool valueAttached = false;
    if (looksLong(a)) {
      const auto eq = a.find('=');
      opt = findLong(app, a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2));
      valueAttached = eq != std::string::npos;
    } else if (looksShort(a)) {
      const std::string name(1, a[1]);
      opt = findShort(app, name);
      if (opt == nullptr && isDigit(a[1])) continue;  // a negative number: a value
      // "-qv": flags in a row; "-ofile": the value attached.
      std::size_t k = 1;
      while (opt != nullptr && opt->get_type_size_max() == 0 && k + 1 < a.size()) {
        opt = findShort(app, std::string(1, a[++k]));
      }
      valueAttached = k + 1 < a.size();
    } else {
      continue;  // a positional or a value
    }
    if (opt == nullptr) return unknownMessage(app, a);
    if (!valueAttached) i += valuesTaken(*opt);
  }
  return std::nullopt;
}

}  // namespace

CLI::App* subcommandNamed(CLI::App& app, std::string_view name) {
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == name) return sub;
  }
  return nullptr;
}

std::optional<std::string> unknownOption(CLI::App& app, int argc, char** argv) {
  const std::vector<std::string> args(argv, argv + argc);
  std::size_t first = 1;
  // Options before the command are the program's (--help, --version).
  while (first < args.size() && subcommandNamed(app, args[first]) == nullptr) ++first;
  if (auto m = scan(app, args, 1, first)) return m;
  if (first >= args.size()) return std::nullopt;
  return scan(*subcommandNamed(app, args[first]), args, first + 1, args.size());
}

std::string unknownCommand(CLI::App& app, const std::string& typed) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (!sub->get_name().empty()) names.push_back(sub->get_name());
  }
  return help::unknownName("command", typed, names);
}

}  // namespace vbim::cli
