#include "runs/samples.hpp"

#include <system_error>

namespace vbim::runs {

namespace fs = std::filesystem;

std::vector<fs::path> sampleDirectories() {
  std::vector<fs::path> dirs;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back((self.parent_path() / VBIM_SAMPLES_FROM_BIN).lexically_normal());
  dirs.push_back(fs::path(VBIM_SOURCE_DIR) / "streams" / "samples");
  return dirs;
}

std::optional<fs::path> findSamples(const std::vector<std::string>& names) {
  for (const fs::path& dir : sampleDirectories()) {
    bool all = true;
    for (const std::string& name : names) {
      std::error_code ec;
      all = all && fs::is_regular_file(dir / name, ec);
    }
    if (all) return dir;
  }
  return std::nullopt;
}

}  // namespace vbim::runs
