#include "plots/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "runtime/error.hpp"

namespace vbim::plots {

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::filesystem::path tmp =
      path.parent_path() / ("." + path.filename().string() + "." + std::to_string(::getpid()) + ".tmp");
  const auto fail = [&](const std::string& why) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw Error(path.string() + ": cannot write the plot: " + why);
  };
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) fail(std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const int writeErrno = errno;
  if (std::fclose(f) != 0 || !written) fail(std::strerror(written ? errno : writeErrno));
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) fail(ec.message());
}

}  // namespace vbim::plots
