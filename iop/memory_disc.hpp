// A disc held in memory: files placed at chosen LBAs, every other sector zero. For tests, tools
// and benchmarks that need a disc layout without an image on the host file system. Sectors that
// belong to no file read as zeros; fillPattern() stamps each sector with its own LBA so a reader
// can check that it received the right data.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "iop/sector_source.hpp"

namespace vbim::iop {

class MemoryDisc final : public SectorSource {
 public:
  explicit MemoryDisc(std::int64_t sectors, std::string name = "memory disc");

  // Places a file whose bytes are given. Throws DiscError if it overlaps another or the disc end.
  void addFile(std::string path, std::int64_t lba, std::vector<std::uint8_t> bytes);
  // Places a file of `sectors` sectors whose content is the LBA pattern (see patternByte).
  void addPatternFile(std::string path, std::int64_t lba, std::int64_t sectors);
  // Byte i of the pattern sector at `lba`: little-endian LBA in bytes 0..7, then (lba + i) & 0xFF.
  static std::uint8_t patternByte(std::int64_t lba, std::size_t i);

  std::int64_t sectorCount() const override { return sectors_; }
  SectorReadResult read(std::int64_t lba, SectorSpan out) override;
  std::optional<DiscFile> find(std::string_view path) const override;
  std::string describe() const override { return name_; }

 private:
  struct Placed {
    DiscFile file;
    std::vector<std::uint8_t> bytes;  // empty: LBA pattern
  };
  std::int64_t sectors_;
  std::string name_;
  std::map<std::int64_t, Placed> files_;  // by start LBA
};

}  // namespace vbim::iop
