// A bare stream file as a disc: the disc holds that one file starting at a configurable LBA, and
// nothing else (sectors before the file read as zeros). Where the file lies changes the CAV rate
// and the seeks, as on hardware. Standard library only.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "iop/sector_file.hpp"
#include "iop/sector_source.hpp"

namespace vbim::iop {

// Where a bare stream file lies on the notional disc (`vbim play`, player::Scenario::bareFile, the
// sweeps): past a small file system, near the hub (the slowest CAV rate, so timings err on the safe
// side).
inline constexpr std::int64_t kBareFileLba = 2048;
// Zero sectors after the file on the disc, so the drive's read-ahead never runs off the disc.
inline constexpr std::int64_t kBareFilePadSectors = 1024;

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

// A bare stream file placed at kBareFileLba with kBareFilePadSectors of zeros after it. Throws
// DiscError as FileDisc does.
std::shared_ptr<FileDisc> bareFileDisc(const std::string& path);

}  // namespace vbim::iop
