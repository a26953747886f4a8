#include "help/man_page.hpp"

#include <sstream>

namespace vbim::help {

namespace {

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

// "\fB\-o\fR, \fB\-\-out\fR".
std::string boldNames(const OptionDoc& opt) {
  std::string names;
  for (const std::string& n : opt.names) names += (names.empty() ? "" : ", ") + ("\\fB" + roff(n) + "\\fR");
  return names;
}

void writeCommand(std::ostream& m, const CommandDoc& cmd) {
  std::string usage = "vbim " + cmd.name;
  for (const OptionDoc& opt : cmd.options) {
    if (opt.positional) usage += " " + opt.names.front();
  }
  m << ".SS \"" << roff(usage) << " [OPTIONS]\"\n" << roffLines(cmd.description);
  for (const OptionDoc& opt : cmd.options) {
    std::string head;
    if (!opt.positional) {
      head = boldNames(opt);
      if (!opt.valueText.empty()) head += " \\fI" + roff(opt.valueText) + "\\fR";
    } else {
      head = "\\fI" + roff(opt.names.front()) + "\\fR";
    }
    m << ".TP\n" << head << "\n" << roffLines(opt.description);
  }
  if (!cmd.footer.empty()) m << ".PP\n.nf\n" << roffLines(cmd.footer) << ".fi\n";
}

}  // namespace

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

std::string manPage(const ProgramDoc& program) {
  std::ostringstream m;
  m << ".TH VBIM 1 \"\" \"vbim " << program.version << "\" \"User Commands\"\n"
    << ".SH NAME\nvbim \\- a simulator of the PlayStation 2 video\\-based illumination map pipeline\n"
    << ".SH SYNOPSIS\n.B vbim\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n.br\n.B vbim help\n\\fICOMMAND\\fR\n"
    << ".SH DESCRIPTION\n"
    << roffLines(program.description) << ".PP\n"
    << roffLines(program.footer);
  m << ".SH OPTIONS\n";
  for (const OptionDoc& opt : program.options) m << ".TP\n" << boldNames(opt) << "\n" << roffLines(opt.description);
  m << ".SH COMMANDS\n";
  for (const CommandDoc& cmd : program.commands) writeCommand(m, cmd);
  const ExitDoc& exits = program.exits;
  m << ".SH \"EXIT STATUS\"\n"
    << ".TP\n"
    << exits.done << "\ndone: every output is complete (and a \\-\\-check or \\-\\-compare found no difference)\n"
    << ".TP\n"
    << exits.failure
    << "\na failure while running (an output that cannot be written, out of memory), or a difference found by "
       "\\fBvbim vectors \\-\\-check\\fR or \\fBvbim replay \\-\\-compare\\fR\n"
    << ".TP\n"
    << exits.badInput
    << "\nbad usage or bad input, refused before any work (an unknown option, a number out of range, a missing file, "
       "a config or stream that fails validation, an output that exists without \\-\\-force)\n"
    << ".TP\n"
    << exits.shardsMissing
    << "\n\\fBvbim profile \\-\\-plan \\-\\-merge\\fR found shards missing or unfinished: each is named with "
       "how to run it again; nothing written\n";
  for (const ExitDoc::Signal& s : exits.signals) {
    m << ".TP\n"
      << s.status << "\nstopped by " << roff(s.name)
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

}  // namespace vbim::help
