#include "streams/disc/standard_input.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace vbim::streams {

namespace {

std::string& stdinFile() {
  static std::string path;  // empty until stdin was read
  return path;
}

// Writes all of `n` bytes, or returns false.
bool writeAll(int fd, const char* data, ssize_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, static_cast<std::size_t>(n));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= w;
  }
  return true;
}

}  // namespace

int copyIntoMemoryFile(int fd, std::uint64_t limit, std::string& problem) {
  const int out = ::memfd_create("vbim-stdin", MFD_CLOEXEC);
  if (out < 0) {
    problem = std::string("<stdin>: cannot hold standard input in memory (") + std::strerror(errno) + ")";
    return -1;
  }
  std::vector<char> buffer(1 << 16);
  std::uint64_t held = 0;
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      problem = std::string("<stdin>: cannot be read (") + std::strerror(errno) + ")";
    } else if (n == 0) {
      return out;
    } else if (held + static_cast<std::uint64_t>(n) > limit) {
      problem = "<stdin>: more than " + std::to_string(limit) +
                " bytes (expected a stream no larger than a dual-layer DVD); give a file instead";
    } else if (!writeAll(out, buffer.data(), n)) {
      problem = std::string("<stdin>: cannot hold standard input in memory (") + std::strerror(errno) + ")";
    } else {
      held += static_cast<std::uint64_t>(n);
      continue;
    }
    ::close(out);
    return -1;
  }
}

std::string readStandardInput(std::string& path) {
  if (!stdinFile().empty()) return "'-' (standard input) can be read only once";
  std::string problem;
  const int fd = copyIntoMemoryFile(STDIN_FILENO, kStdinLimitBytes, problem);
  if (fd < 0) return problem;
  // The descriptor stays open for the whole process: its /proc path is the file.
  stdinFile() = "/proc/self/fd/" + std::to_string(fd);
  path = stdinFile();
  return {};
}

bool isStandardInput(const std::string& path) {
  return !stdinFile().empty() && path == stdinFile();
}

std::string nameStandardInput(std::string text) {
  const std::string& path = stdinFile();
  if (path.empty()) return text;
  for (auto at = text.find(path); at != std::string::npos; at = text.find(path, at + 7)) {
    text.replace(at, path.size(), "<stdin>");
  }
  return text;
}

}  // namespace vbim::streams
