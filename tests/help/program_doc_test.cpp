// The man page and the completions from a small program description: what each kind of option
// becomes, and the escapes roff and zsh need.
#include <string>

#include <gtest/gtest.h>

#include "help/man_page.hpp"
#include "help/program_doc.hpp"
#include "help/shell_completion.hpp"

namespace vbim::help {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

ProgramDoc tinyProgram() {
  ProgramDoc p;
  p.version = "9.8.7";
  p.description = "vbim: a test\n.starts with a dot";
  p.footer = "See 'vbim help CMD'.";
  p.options.push_back(OptionDoc{{"-h", "--help"}, false, false, "", "Print help", ValueKind::None, {}, false});
  CommandDoc play{"play", "Play a stream [fast]: really\nsecond line", "Examples:\n  vbim play a.vbim\n", {}};
  play.options.push_back(OptionDoc{{"stream"}, true, false, "", "A stream file", ValueKind::File, {}, false});
  play.options.push_back(
      OptionDoc{{"-o", "--out"}, false, false, "TEXT", "Output directory", ValueKind::File, {}, false});
  play.options.push_back(
      OptionDoc{{"--format"}, false, false, "TEXT=png", "It's png or exr", ValueKind::Choice, {"png", "exr"}, false});
  play.options.push_back(
      OptionDoc{{"--policy"}, false, false, "TEXT", "Policies", ValueKind::Choice, {"hard-skip", "play-late"}, true});
  play.options.push_back(OptionDoc{{"--seed"}, false, false, "UINT=1", "Seed", ValueKind::Number, {}, false});
  play.options.push_back(OptionDoc{{"--frames"}, false, false, "DIR", "Frames", ValueKind::Directory, {}, false});
  play.options.push_back(OptionDoc{{"--force"}, false, false, "", "Replace", ValueKind::None, {}, false});
  p.commands.push_back(play);
  CommandDoc profile{"profile", "Sweep", "", {}};
  profile.options.push_back(OptionDoc{{"streams"}, true, true, "", "Streams", ValueKind::File, {}, false});
  p.commands.push_back(profile);
  p.exits.signals.push_back({"SIGTERM", 143});
  return p;
}

TEST(ManPage, EscapesRoffAndListsEveryOption) {
  const std::string m = manPage(tinyProgram());
  EXPECT_EQ(m.rfind(".TH VBIM 1 \"\" \"vbim 9.8.7\" \"User Commands\"\n", 0), 0u);
  EXPECT_TRUE(has(m, "\\&.starts with a dot\n"));  // a text line, not a request
  EXPECT_TRUE(has(m, ".TP\n\\fB\\-h\\fR, \\fB\\-\\-help\\fR\nPrint help\n"));
  EXPECT_TRUE(has(m, ".SS \"vbim play stream [OPTIONS]\"\n"));
  EXPECT_TRUE(has(m, ".TP\n\\fIstream\\fR\nA stream file\n"));
  EXPECT_TRUE(has(m, ".TP\n\\fB\\-o\\fR, \\fB\\-\\-out\\fR \\fITEXT\\fR\nOutput directory\n"));
  EXPECT_TRUE(has(m, ".TP\n\\fB\\-\\-force\\fR\nReplace\n"));
  EXPECT_TRUE(has(m, ".PP\n.nf\nExamples:\n  vbim play a.vbim\n.fi\n"));
  EXPECT_TRUE(has(m, ".TP\n143\nstopped by SIGTERM:"));
  EXPECT_EQ(roff("a-b\\c"), "a\\-b\\ec");
}

TEST(BashCompletion, OffersEachKindOfValue) {
  const std::string b = bashCompletion(tinyProgram());
  EXPECT_TRUE(has(b, "local commands=\"help play profile\"\n"));
  EXPECT_TRUE(has(b, "opts=\"-o --out --format --policy --seed --frames --force\"\n"));
  EXPECT_TRUE(has(b, "--format) _vbim_values \"png exr\"; return ;;\n"));
  EXPECT_TRUE(has(b, "--policy) _vbim_values \"hard-skip play-late\" list; return ;;\n"));
  EXPECT_TRUE(has(b, "--seed) return ;;  # a number"));
  EXPECT_TRUE(has(b, "--frames) COMPREPLY=($(compgen -d -- \"$cur\")); return ;;\n"));
  EXPECT_FALSE(has(b, "--force)"));  // a flag: nothing follows it
}

TEST(ZshCompletion, QuotesDescriptionsAndOffersEachKindOfValue) {
  const std::string z = zshCompletion(tinyProgram());
  EXPECT_TRUE(has(z, "'play:Play a stream \\[fast\\]\\: really'\n"));  // the first line only
  EXPECT_TRUE(has(z, "':stream:_files'"));
  EXPECT_TRUE(has(z, "'*:streams:_files'"));  // several positional values
  EXPECT_TRUE(has(z, "'(-o --out)'{-o,--out}'[Output directory]:value:_files'"));
  EXPECT_TRUE(has(z, "'--format[It'\\''s png or exr]:value:(png exr)'"));
  EXPECT_TRUE(has(z, "'--policy[Policies]:value:_values -s , value hard-skip play-late'"));
  EXPECT_TRUE(has(z, "'--seed[Seed]:number: '"));
  EXPECT_TRUE(has(z, "'--frames[Frames]:directory:_files -/'"));
  EXPECT_TRUE(has(z, "'--force[Replace]'"));
}

}  // namespace
}  // namespace vbim::help
