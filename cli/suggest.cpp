#include "cli/suggest.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace vbim::cli {

namespace {

// Optimal string alignment distance (Damerau-Levenshtein without repeated edits of a substring).
std::size_t editDistance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

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

CLI::App* subcommandNamed(CLI::App& app, const std::string& name) {
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == name) return sub;
  }
  return nullptr;
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
  std::vector<std::string> close;
  if (name.rfind("--", 0) == 0) close = closestNames(name, longNames(app));
  return "unknown option '" + name + "'" + didYouMean(close);
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

std::vector<std::string> closestNames(std::string_view typed, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::clamp<std::size_t>(typed.size() / 3, 1, 3);
  std::size_t best = std::numeric_limits<std::size_t>::max();
  std::vector<std::string> out;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(typed, c);
    if (d > limit || d > best) continue;
    if (d < best) out.clear();
    best = d;
    if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  }
  if (!out.empty() || typed.size() < 3) return out;
  for (const std::string& c : candidates) {
    if (c.size() > typed.size() && c.compare(0, typed.size(), typed) == 0) out.push_back(c);
  }
  if (out.size() > 1) out.clear();  // a prefix of several names says nothing
  return out;
}

std::string didYouMean(const std::vector<std::string>& names) {
  if (names.empty()) return {};
  std::string s = " (did you mean ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) s += i + 1 == names.size() ? " or " : ", ";
    s += "'" + names[i] + "'";
  }
  return s + "?)";
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
  return "unknown command '" + typed + "'" + didYouMean(closestNames(typed, names));
}

}  // namespace vbim::cli
