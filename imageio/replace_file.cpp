#include "imageio/replace_file.hpp"

#include <system_error>

#include "imageio/error.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& path) {
  return path.parent_path() / ("." + path.stem().string() + ".tmp" + path.extension().string());
}

void writeThenRename(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
  const fs::path temporary = temporaryPathFor(path);
  try {
    write(temporary);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw ImageIoError(path.string() + ": cannot move the finished image into place: " + ec.message());
  }
}

void writePlaced(const fs::path& path, FilePlacement placement,
                 const std::function<void(const fs::path& file)>& write) {
  if (placement == FilePlacement::TemporaryThenRename) {
    writeThenRename(path, write);
    return;
  }
  try {
    write(path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(path, ignored);
    throw;
  }
}

}  // namespace vbim::imageio
