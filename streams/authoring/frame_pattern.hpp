// A numbered image sequence named by a printf-style pattern: 'dir/lightmap_%04d.exr' matches
// dir/lightmap_0000.exr, dir/lightmap_0001.exr, ... The numbers must be consecutive.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vbim::streams {

struct FrameFile {
  int number = 0;
  std::filesystem::path path;
};

// The files matching `pattern`, in number order. Throws AuthoringError naming the pattern when none
// matches, the directory is missing, the pattern is malformed or a number is missing in the run.
std::vector<FrameFile> expandFramePattern(const std::string& pattern);

// `pattern` with its number field replaced by `number` (for messages about a missing file).
std::string formatFramePattern(const std::string& pattern, int number);

}  // namespace vbim::streams
