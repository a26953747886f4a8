// Every picture is written under a temporary name beside its final one and renamed into place when
// complete: a reader never sees half a file, and a failed write leaves nothing behind.
#pragma once

#include <filesystem>
#include <functional>

namespace vbim::imageio {

// The temporary name of `path`: ".<stem>.tmp<extension>" in the same directory (same file system,
// so the rename is atomic; same extension, so writers that choose the format by it still can).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

// Calls `write` with the temporary path, then renames the result to `path`. If `write` throws, the
// temporary file is removed and the exception passes on; a failed rename throws ImageIoError.
void writeThenRename(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace vbim::imageio
