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

// Numbers are read strictly: no wrap of "-1" to 2^64-1, no clamp, no text after the digits.
TEST(OptionText, NumbersAreReadStrictly) {
  EXPECT_EQ(wholeNumberProblem("42", false), "");
  EXPECT_EQ(wholeNumberProblem("+42", false), "");
  EXPECT_EQ(wholeNumberProblem("-1", true), "");
  EXPECT_EQ(wholeNumberProblem("-1", false), "'-1' is negative; expected a whole number 0 or more");
  EXPECT_EQ(wholeNumberProblem("", false), "expected a whole number, found nothing");
  EXPECT_EQ(wholeNumberProblem("12x", true), "'12x' is not a whole number");
  EXPECT_EQ(wholeNumberProblem("1e3", false), "'1e3' is not a whole number");
  EXPECT_EQ(wholeNumberProblem("18446744073709551616", false),
            "'18446744073709551616' is out of range (at most 18446744073709551615)");
  EXPECT_EQ(wholeNumberProblem("9223372036854775808", true),
            "'9223372036854775808' is out of range (at most 9223372036854775807)");
  EXPECT_EQ(numberProblem("2.5"), "");
  EXPECT_EQ(numberProblem("-1e3"), "");
  EXPECT_EQ(numberProblem("2.5s"), "'2.5s' is not a number");
  EXPECT_EQ(numberProblem("1e999"), "'1e999' is out of range");
  EXPECT_EQ(numberProblem("nan"), "'nan' is not a finite number");
}

}  // namespace
