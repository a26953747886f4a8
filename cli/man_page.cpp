#include "cli/man_page.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include "cli/app_tree.hpp"
#include "cli/command.hpp"

namespace vbim::cli {

namespace {

std::string roff(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      out += "\\-";
    } else {
      out += c;
    }
  }
  return out;
}

// Text lines: a line that starts with '.' or '\'' would be a request; \& keeps it text.
std::string roffLines(const std::string& s) {
  std::istringstream in(s);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && (line[0] == '.' || line[0] == '\'')) out += "\\&";
    out += roff(line) + "\n";
  }
  return out;
}

}  // namespace

std::string manPage(CLI::App& app) {
  const auto formatter = std::dynamic_pointer_cast<CLI::Formatter>(app.get_formatter());
  std::ostringstream m;
  m << ".TH VBIM 1 \"\" \"vbim " << VBIM_VERSION << "\" \"User Commands\"\n"
    << ".SH NAME\nvbim \\- a simulator of the PlayStation 2 video\\-based illumination map pipeline\n"
    << ".SH SYNOPSIS\n.B vbim\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n.br\n.B vbim help\n\\fICOMMAND\\fR\n"
    << ".SH DESCRIPTION\n"
    << roffLines(app.get_description()) << ".PP\n"
    << roffLines(app.get_footer());
  m << ".SH OPTIONS\n";
  for (const CLI::Option* opt : namedOptions(app)) {
    std::string names;
    for (const std::string& n : optionNames(*opt)) names += (names.empty() ? "" : ", ") + ("\\fB" + roff(n) + "\\fR");
    m << ".TP\n" << names << "\n" << roffLines(opt->get_description());
  }
  m << ".SH COMMANDS\n";
  for (CLI::App* cmd : listedCommands(app)) {
    std::string usage = "vbim " + cmd->get_name();
    for (const CLI::Option* opt : cmd->get_options({})) {
      if (!opt->nonpositional()) usage += " " + opt->get_name();
    }
    m << ".SS \"" << roff(usage) << " [OPTIONS]\"\n" << roffLines(cmd->get_description());
    for (const CLI::Option* opt : cmd->get_options({})) {
      std::string head;
      if (opt->nonpositional()) {
        for (const std::string& n : optionNames(*opt)) head += (head.empty() ? "" : ", ") + ("\\fB" + roff(n) + "\\fR");
        const std::string opts = formatter ? formatter->make_option_opts(opt) : std::string();
        if (!opts.empty()) head += " \\fI" + roff(opts.substr(opts.find_first_not_of(' '))) + "\\fR";
      } else {
        head = "\\fI" + roff(opt->get_name()) + "\\fR";
      }
      m << ".TP\n" << head << "\n" << roffLines(opt->get_description());
    }
    if (!cmd->get_footer().empty()) m << ".PP\n.nf\n" << roffLines(cmd->get_footer()) << ".fi\n";
  }
  m << ".SH \"EXIT STATUS\"\n"
    << ".TP\n0\ndone; every output is complete\n"
    << ".TP\n2\nbad usage or bad input (an unknown option, a number out of range, a missing file, a config or "
       "stream that fails validation, an output that exists without \\-\\-force)\n"
    << ".TP\n1\na failure while running (an output that cannot be written, out of memory)\n"
    << ".TP\n130\ninterrupted (Ctrl\\-C); temporary files removed\n"
    << ".SH \"SEE ALSO\"\nThe documentation installed in share/doc/vbim (cli.md: the command line; player.md: "
       "the outputs of a run).\n";
  return m.str();
}

}  // namespace vbim::cli
