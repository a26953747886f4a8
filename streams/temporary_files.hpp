// The hidden temporary names under which vbim writes an output before renaming it into place
// (an output is complete or absent), and the removal of those that dead processes left behind.
//
// A command that is killed (SIGKILL, a second Ctrl-C, a crash) cannot remove its temporary output;
// the next command that writes into the same directory removes it, once the process that made it
// is gone (its PID is in the name), so no leftover outlives the next run and no live run's work
// is touched.
#pragma once

#include <filesystem>

namespace vbim::streams {

// ".NAME.tmp-PID" beside `target`, PID being this process's.
std::filesystem::path temporarySibling(const std::filesystem::path& target);

// Removes every ".NAME.tmp-PID" (file or directory, and the ".NAME.tmp-PID.old" a replaced output
// is moved to) in `dir` whose process no longer runs. Returns how many were removed; never throws
// (a leftover that cannot be removed stays, and the next run tries again).
int removeStaleTemporaries(const std::filesystem::path& dir);

}  // namespace vbim::streams
