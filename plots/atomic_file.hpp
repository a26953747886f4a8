// Writes a file so that it is complete or absent: the bytes go to a temporary name in the same
// directory, which is renamed onto the final name once they are all written.
#pragma once

#include <filesystem>
#include <string_view>

namespace vbim::plots {

// Throws Error naming `path` when the file cannot be written (the temporary file is removed).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace vbim::plots
