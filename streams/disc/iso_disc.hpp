// An ISO 9660 image (made with xorriso, genisoimage or any mastering tool) as a disc for the drive
// model. Files are found by path as sceCdSearchFile does ("\\VIDEO\\DAY.PSS;1", "/video/day.pss");
// their LBAs are the image's, so where a file lies changes seeks and the CAV rate as on hardware.
// The volume descriptor and directories are read by our own checked reader (iso9660_records.hpp,
// iso9660_tree.hpp): every field is validated before it is followed, so a damaged image gives a
// DiscError, never a read out of bounds.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "iop/sector_file.hpp"
#include "iop/sector_source.hpp"

namespace vbim::streams::iso9660 {
class DirectoryTree;
}

namespace vbim::streams {

class IsoDisc final : public iop::SectorSource {
 public:
  // Opens and checks the image. Throws iop::DiscError when it is missing, unreadable, not ISO 9660
  // (no primary volume descriptor in the set starting at LBA 16), damaged (a descriptor field that
  // fails its check, a root directory outside the volume) or truncated (shorter than its volume size).
  explicit IsoDisc(std::string path);
  ~IsoDisc() override;
  IsoDisc(const IsoDisc&) = delete;
  IsoDisc& operator=(const IsoDisc&) = delete;

  std::int64_t sectorCount() const override { return sectors_; }
  iop::SectorReadResult read(std::int64_t lba, iop::SectorSpan out) override;
  // Matches names case-insensitively, ignoring the ";version" and a trailing '.'. Throws
  // iop::DiscError naming the image and the file when it runs past the end of the volume or is not
  // one contiguous extent (multi-extent or interleaved), or when a directory on the way is damaged.
  std::optional<iop::DiscFile> find(std::string_view path) const override;
  std::string describe() const override { return path_; }
  // Every file on the volume, in directory order (depth first), named as sceCdSearchFile names them
  // ("\\DATA\\DAY.VBI;1"), with its LBA and length. Multi-extent and interleaved files, directories
  // below level 8 and directories already listed (loops, repeated links) are left out; a damaged
  // record or a file running past the volume's end is a DiscError naming it.
  std::vector<iop::DiscFile> files() const;

  // "\\VIDEO\\DAY.PSS;1" -> "/video/day.pss": the form find() compares, level by level.
  static std::string normalisePath(std::string_view path);

 private:
  // Reads sector `lba` into `out`; false when the image cannot give it.
  bool readSector(std::int64_t lba, iop::SectorSpan out) const;

  std::string path_;
  mutable iop::SectorFile file_;
  mutable std::mutex fileMutex_;  // one read at a time on file_ (its window is shared)
  std::int64_t sectors_ = 0;
  std::unique_ptr<iso9660::DirectoryTree> tree_;
};

}  // namespace vbim::streams
