// Where the sample streams (streams/samples/*.vbim) are, for commands whose default input is a
// sample (`vbim vectors`, vectors_run.hpp): the default must not depend on the directory the command
// is run from.
// Looked for, in order:
//   1. <directory of this program>/VBIM_SAMPLES_FROM_BIN: an installed vbim (bin/vbim) finds
//      share/vbim/samples of the same prefix, where cmake/Install.cmake puts them;
//   2. VBIM_SOURCE_DIR/streams/samples: a vbim run from its build tree finds the source tree's.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vbim::runs {

// The directories looked in, in order (whether or not they exist).
std::vector<std::filesystem::path> sampleDirectories();

// The first directory of sampleDirectories() holding every file of `names`, or nullopt.
std::optional<std::filesystem::path> findSamples(const std::vector<std::string>& names);

}  // namespace vbim::runs
