#include "cli/stdin_input.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace vbim::cli {

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

// Standard input copied into a memfd; "" on success, else what went wrong.
std::string readStdin() {
  if (!stdinFile().empty()) return "'-' (standard input) can be read only once";
  const int fd = ::memfd_create("vbim-stdin", MFD_CLOEXEC);
  if (fd < 0) return std::string("<stdin>: cannot hold standard input in memory (") + std::strerror(errno) + ")";
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::string("<stdin>: cannot be read (") + std::strerror(errno) + ")";
    if (n == 0) break;
    if (!writeAll(fd, buffer.data(), n)) {
      return std::string("<stdin>: cannot hold standard input in memory (") + std::strerror(errno) + ")";
    }
  }
  // The descriptor stays open for the whole process: its /proc path is the file.
  stdinFile() = "/proc/self/fd/" + std::to_string(fd);
  return {};
}

}  // namespace

const CLI::Validator& stdinAsFile() {
  static const CLI::Validator v(
      [](std::string& s) {
        if (s != "-") return std::string();
        std::string problem = readStdin();
        if (problem.empty()) s = stdinFile();
        return problem;
      },
      "", "stdin");
  return v;
}

bool isStdin(const std::string& path) {
  return !stdinFile().empty() && path == stdinFile();
}

std::string nameStdin(std::string text) {
  const std::string& path = stdinFile();
  if (path.empty()) return text;
  for (auto at = text.find(path); at != std::string::npos; at = text.find(path, at + 7)) {
    text.replace(at, path.size(), "<stdin>");
  }
  return text;
}

}  // namespace vbim::cli
