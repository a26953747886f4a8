// A bare stream file as a disc: the disc holds that one file starting at a configurable LBA, and
// nothing else (sectors before the file read as zeros). Where the file lies changes the CAV rate
// and the seeks, as on hardware. Standard library only.
#pragma once

#include <cstdint>
#include <string>

#include "iop/sector_file.hpp"
#include "iop/sector_source.hpp"

namespace vbim::iop {

class FileDisc final : public SectorSource {
 public:
  // Opens `path`. Throws DiscError when the file is missing, unreadable, empty, or not a whole
  // number of 2048-byte sectors (a stream of 2048-byte packs cut short), naming the byte offset.
  // `discSectors` = 0: the disc ends with the file; otherwise the disc has that many sectors
  // (must hold the file).
  FileDisc(std::string path, std::int64_t startLba, std::int64_t discSectors = 0);

  std::int64_t sectorCount() const override { return discSectors_; }
  SectorReadResult read(std::int64_t lba, SectorSpan out) override;
  std::optional<DiscFile> find(std::string_view path) const override;
  std::string describe() const override;

  const DiscFile& file() const { return file_; }

 private:
  std::string path_;
  SectorFile in_;
  DiscFile file_;
  std::int64_t discSectors_ = 0;
};

}  // namespace vbim::iop
