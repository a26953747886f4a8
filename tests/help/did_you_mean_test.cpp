#include "help/did_you_mean.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vbim::help {
namespace {

const std::vector<std::string> kOptions{"--out", "--output-format", "--seed", "--stream", "--force"};

TEST(ClosestNames, OneEditAwayIsNamed) {
  EXPECT_EQ(closestNames("--outt", kOptions), std::vector<std::string>{"--out"});
  EXPECT_EQ(closestNames("--sed", kOptions), std::vector<std::string>{"--seed"});
}

TEST(ClosestNames, SwappedNeighboursCountOne) {
  // Optimal string alignment: "fro" -> "for" is one transposition, not two changes.
  EXPECT_EQ(closestNames("--froce", kOptions), std::vector<std::string>{"--force"});
}

TEST(ClosestNames, EveryNameAtTheSmallestDistanceOnce) {
  const std::vector<std::string> names{"play", "plan", "play"};
  EXPECT_EQ(closestNames("pla", names), (std::vector<std::string>{"play", "plan"}));
}

TEST(ClosestNames, FarNamesAreNotOffered) {
  EXPECT_TRUE(closestNames("--zzzzzz", kOptions).empty());
  // A short typo may be one edit from anything: at most a third of its length, at least 1.
  EXPECT_TRUE(closestNames("ab", {"xyz"}).empty());
}

TEST(ClosestNames, AnUnambiguousPrefixIsNamed) {
  EXPECT_EQ(closestNames("--output", kOptions), std::vector<std::string>{"--output-format"});
  // A prefix of several names says nothing.
  EXPECT_TRUE(closestNames("--st", {"--stream", "--stall"}).empty());
}

TEST(DidYouMean, ListsTheNames) {
  EXPECT_EQ(didYouMean({}), "");
  EXPECT_EQ(didYouMean({"--out"}), " (did you mean '--out'?)");
  EXPECT_EQ(didYouMean({"a", "b"}), " (did you mean 'a' or 'b'?)");
  EXPECT_EQ(didYouMean({"a", "b", "c"}), " (did you mean 'a', 'b' or 'c'?)");
}

}  // namespace
}  // namespace vbim::help
