#include "streams/temporary_files.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace vbim::streams {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMarker = ".tmp-";

// The PID in ".NAME.tmp-PID" or ".NAME.tmp-PID.old", or 0 if `name` is not such a name.
long temporaryOwner(std::string_view name) {
  if (name.size() < 2 || name[0] != '.') return 0;
  if (name.ends_with(".old")) name.remove_suffix(4);
  const std::size_t at = name.rfind(kMarker);
  if (at == std::string_view::npos || at == 0) return 0;
  const std::string_view digits = name.substr(at + kMarker.size());
  long pid = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty() || pid <= 0) return 0;
  return pid;
}

// Only a process that certainly no longer exists (ESRCH): one we may not signal (EPERM) still runs.
bool processIsGone(long pid) {
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

fs::path temporarySibling(const fs::path& target) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  return dir / ("." + target.filename().string() + std::string(kMarker) + std::to_string(::getpid()));
}

int removeStaleTemporaries(const fs::path& dir) {
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec);
  if (ec) return 0;
  std::vector<fs::path> stale;  // listed first: the directory is not changed while it is read
  for (const fs::directory_entry& e : it) {
    const long pid = temporaryOwner(e.path().filename().string());
    if (pid != 0 && pid != ::getpid() && processIsGone(pid)) stale.push_back(e.path());
  }
  int removed = 0;
  for (const fs::path& p : stale) {
    std::error_code rm;
    if (fs::remove_all(p, rm) > 0 && !rm) ++removed;
  }
  return removed;
}

}  // namespace vbim::streams
