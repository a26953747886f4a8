#include "cli/man_page.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include "cli/app_tree.hpp"
#include "cli/command.hpp"
#include "cli/exit_status.hpp"

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
  // From the codes the program ends with (cli/exit_status.hpp).
  m << ".SH \"EXIT STATUS\"\n"
    << ".TP\n"
    << kExitDone << "\ndone: every output is complete (and a \\-\\-check or \\-\\-compare found no difference)\n"
    << ".TP\n"
    << kExitFailure
    << "\na failure while running (an output that cannot be written, out of memory), or a difference found by "
       "\\fBvbim vectors \\-\\-check\\fR or \\fBvbim replay \\-\\-compare\\fR\n"
    << ".TP\n"
    << kExitBadInput
    << "\nbad usage or bad input, refused before any work (an unknown option, a number out of range, a missing file, "
       "a config or stream that fails validation, an output that exists without \\-\\-force)\n";
  for (const StopSignal& s : kStopSignals) {
    m << ".TP\n"
      << exitForSignal(s.number) << "\nstopped by " << roff(s.name)
      << ": temporary files removed, outputs left as they were (128 + the signal's number)\n";
  }
  m << ".SH ENVIRONMENT\n"
    << ".TP\n\\fBVBIM_PROGRESS\\fR=1\nprogress lines on stderr even when it is not a terminal, at most one every 5 s\n"
    << ".TP\n\\fBSOURCE_DATE_EPOCH\\fR\nthe date \\fBvbim author \\-\\-iso\\fR records in a disc image (default: "
       "2000\\-01\\-01 "
       "00:00 UTC, so that images are reproducible)\n"
    << ".SH FILES\n"
    << ".TP\n\\fI.NAME.tmp\\-PID\\fR\n"
       "an output being written, hidden beside NAME and renamed to it when complete; removed on an error or a "
       "signal, and by the next command that writes into the same directory once process PID is gone\n"
    << ".TP\n\\fIshare/bash\\-completion/completions/vbim\\fR, \\fIshare/zsh/site\\-functions/_vbim\\fR\n"
       "the bash and zsh completions, generated with this page from the same option definitions\n"
    << ".SH \"SEE ALSO\"\n"
    << "\\fBvbim help\\fR \\fICOMMAND\\fR; the documentation installed in \\fIshare/doc/vbim\\fR: "
       "\\fIREADME.md\\fR, \\fIcli.md\\fR (the command line), \\fIplayer.md\\fR and \\fIrun\\-files.md\\fR "
       "(the outputs of a run, with units), \\fIfault\\-plans.md\\fR, \\fIporting.md\\fR.\n";
  return m.str();
}

}  // namespace vbim::cli
