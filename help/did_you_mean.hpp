// "Did you mean": the real names a mistyped one most likely comes from, and the words that offer
// them. The command line's scan of its arguments (cli/suggest.hpp) asks with the names it knows.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vbim::help {

// The names of `candidates` a typo of `typed` would most likely come from: those at the smallest
// edit distance (optimal string alignment: inserting, deleting or changing a letter, or swapping two
// neighbours, counts 1), if it is at most a third of the length (at least 1, at most 3); else the
// one name `typed` is a prefix of (3 letters or more). Empty when nothing is close.
std::vector<std::string> closestNames(std::string_view typed, const std::vector<std::string>& candidates);

// " (did you mean 'a'?)" or " (did you mean 'a' or 'b'?)", or "" when `names` is empty.
std::string didYouMean(const std::vector<std::string>& names);

}  // namespace vbim::help
