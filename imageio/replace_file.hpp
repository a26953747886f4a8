// Every picture is written under a temporary name beside its final one and renamed into place when
// complete: a reader never sees half a file, and a failed write leaves nothing behind. Except in a
// directory that is itself staged (runs/output_dir.hpp: a run's directory, written under a
// temporary name and renamed into place only when complete): no reader can see its files before
// then, so a file there is written under its own name (FilePlacement::InStagedDirectory), one
// file created and no rename (issue #31: 34 renames were 5 % of the demo's picture thread, perf).
#pragma once

#include <filesystem>
#include <functional>

namespace vbim::imageio {

// The temporary name of `path`: ".<stem>.tmp<extension>" in the same directory (same file system,
// so the rename is atomic; same extension, so writers that choose the format by it still can).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

enum class FilePlacement {
  TemporaryThenRename,  // writeThenRename
  InStagedDirectory,    // written under its own name; removed if the write fails
};

// Calls `write` with the temporary path, then renames the result to `path`. If `write` throws, the
// temporary file is removed and the exception passes on; a failed rename throws ImageIoError.
void writeThenRename(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

// writeThenRename, or for InStagedDirectory `write` called with `path` itself (and the file removed
// if `write` throws, the exception passing on).
void writePlaced(const std::filesystem::path& path, FilePlacement placement,
                 const std::function<void(const std::filesystem::path& file)>& write);

}  // namespace vbim::imageio
