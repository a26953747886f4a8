// help/option_text: the fixed set in a check's description, --help's type text without the checks'
// bare names, and the words for an unknown option or command.
#include "help/option_text.hpp"

#include <gtest/gtest.h>

namespace {

using namespace vbim::help;

TEST(OptionText, ChoicesAreTheSetOrTheNamesBeforeArrows) {
  EXPECT_EQ(choicesIn("TEXT:{png,exr}"), (std::vector<std::string>{"png", "exr"}));
  EXPECT_EQ(choicesIn("TEXT:value in {crop->0,pad->1,none->2} OR {0,1,2}"),
            (std::vector<std::string>{"crop", "pad", "none"}));
  EXPECT_TRUE(choicesIn("UINT:NONNEGATIVE").empty());
  EXPECT_TRUE(choicesIn("TEXT:{unclosed").empty());
}

TEST(OptionText, TypeTextKeepsTheTypeAndWhatSaysSomething) {
  // Bare names go; a range or limit follows the default in parentheses, its "TYPE " dropped.
  EXPECT_EQ(plainTypeText(" UINT:NONNEGATIVE=1", "UINT:NONNEGATIVE"), " UINT=1");
  EXPECT_EQ(plainTypeText(" INT:INT in [0 - 511]=0", "INT:INT in [0 - 511]"), " INT=0 (in [0 - 511])");
  EXPECT_EQ(plainTypeText(" UINT:NONNEGATIVE:at most the machine's hardware threads=1 [x]",
                          "UINT:NONNEGATIVE:at most the machine's hardware threads"),
            " UINT=1 (at most the machine's hardware threads) [x]");
  EXPECT_EQ(plainTypeText(" TEXT:{png,exr}", "TEXT:{png,exr}"), " TEXT ({png,exr})");
  // Nothing to cut: as it is.
  EXPECT_EQ(plainTypeText(" TEXT=png", "TEXT"), " TEXT=png");
  EXPECT_EQ(plainTypeText(" FLOAT", "UINT:NONNEGATIVE"), " FLOAT");
}

TEST(OptionText, UnknownNamesOfferTheClosest) {
  EXPECT_EQ(unknownName("option", "--outt", {"--out", "--force"}), "unknown option '--outt' (did you mean '--out'?)");
  EXPECT_EQ(unknownName("command", "pla", {"play", "info"}), "unknown command 'pla' (did you mean 'play'?)");
  EXPECT_EQ(unknownName("option", "-x", {}), "unknown option '-x'");
}

}  // namespace
