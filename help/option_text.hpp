// What an option's value is said to be, as text, from an option parser's description of it: a type
// and its checks' descriptions, "TYPE:<description>:<description>" (cli/ gives CLI11's), and the
// words for a name that is no option or command or for a value that is no number. No parser here: text in,
// text out.
#pragma once

#include <string>
#include <vector>

namespace vbim::help {

// The fixed set in a check's description: "{a,b,c}", or "value in {a->1,b->2} OR {1,2}" (the names
// before "->"). Empty if there is none.
std::vector<std::string> choicesIn(const std::string& description);

// --help's text after an option's names (`opts`, " UINT:NONNEGATIVE=1") with its type name
// (`typeName`, "UINT:NONNEGATIVE:at most the machine's hardware threads") cut to the type, and the
// descriptions that say something to a user (a range, a limit: those with a lower-case letter; a
// leading "TYPE " dropped) after the default in parentheses: " UINT=1 (at most the machine's
// hardware threads)". `opts` as it is when the type name has no description or is not in it.
std::string plainTypeText(const std::string& opts, const std::string& typeName);

// What is wrong with `text` as a whole number written plainly (digits after an optional '+', or a '-'
// when `negativeAllowed`; 64 bits at most, never wrapped or clamped), or "" when nothing is: "'-1' is
// negative; expected a whole number 0 or more", "'1e3' is not a whole number", "'99999999999999999999'
// is out of range (at most 18446744073709551615)".
std::string wholeNumberProblem(const std::string& text, bool negativeAllowed);
// The same for a finite decimal number ("'nan' is not a finite number").
std::string numberProblem(const std::string& text);

// "unknown option '--outt' (did you mean '--out'?)": `what` ("option", "command") and `typed`, with
// the closest of `names` (closestNames), if any is close.
std::string unknownName(const std::string& what, const std::string& typed, const std::vector<std::string>& names);

}  // namespace vbim::help
