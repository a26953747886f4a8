// Reads byte ranges of a disc image or stream file through a read-ahead window. The drive model asks
// for one 2048-byte sector at a time; a seek and a read per sector cost two system calls each (26,000
// for a ten-minute 512x512 play), so whole windows of sectors are read at once and later sectors are
// copied from memory. Bytes are the same either way; only host time changes. Standard library only.
// A file that changes under a running play may be seen up to one window late.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace vbim::iop {

class SectorFile {
 public:
  // windowBytes: how much is read at once (a multiple of the sector size keeps reads aligned).
  explicit SectorFile(std::size_t windowBytes = 64 * 1024) : windowBytes_(windowBytes) {}

  // False when the file cannot be opened.
  bool open(const std::string& path);
  // Copies out.size() bytes starting at `offset`; false when the file ends before them or the read
  // fails (out may then hold part of them).
  bool read(std::int64_t offset, std::span<std::uint8_t> out);

 private:
  bool fill(std::int64_t start);

  std::size_t windowBytes_;
  std::ifstream in_;
  std::vector<std::uint8_t> window_;
  std::int64_t windowStart_ = -1;  // file offset of window_[0]; -1: nothing read yet
};

}  // namespace vbim::iop
