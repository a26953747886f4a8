#include "iop/sector_file.hpp"

#include <algorithm>
#include <cstring>

namespace vbim::iop {

bool SectorFile::open(const std::string& path) {
  in_.open(path, std::ios::binary);
  windowStart_ = -1;
  window_.clear();
  return static_cast<bool>(in_);
}

bool SectorFile::fill(std::int64_t start) {
  window_.resize(windowBytes_);
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(start));
  in_.read(reinterpret_cast<char*>(window_.data()), static_cast<std::streamsize>(window_.size()));
  const std::streamsize got = in_.gcount();
  window_.resize(static_cast<std::size_t>(std::max<std::streamsize>(got, 0)));
  windowStart_ = start;
  return got > 0;
}

bool SectorFile::read(std::int64_t offset, std::span<std::uint8_t> out) {
  if (offset < 0) return false;
  const auto inWindow = [&] {
    return windowStart_ >= 0 && offset >= windowStart_ &&
           offset + static_cast<std::int64_t>(out.size()) <= windowStart_ + static_cast<std::int64_t>(window_.size());
  };
  if (!inWindow()) {
    if (out.size() > windowBytes_) {  // larger than a window: read it directly
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(offset));
      in_.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(out.size()));
      return in_.gcount() == static_cast<std::streamsize>(out.size());
    }
    // Windows start at multiples of their size, so a sector never straddles two of them when the
    // size is a multiple of the sector's.
    const auto w = static_cast<std::int64_t>(windowBytes_);
    std::int64_t start = offset / w * w;
    if (offset + static_cast<std::int64_t>(out.size()) > start + w) start = offset;
    if (!fill(start) || !inWindow()) return false;
  }
  std::memcpy(out.data(), window_.data() + (offset - windowStart_), out.size());
  return true;
}

}  // namespace vbim::iop
