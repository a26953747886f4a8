// An ISO 9660 image (made with xorriso, genisoimage or any mastering tool) as a disc for the drive
// model. Files are found by path as sceCdSearchFile does ("\\VIDEO\\DAY.PSS;1", "/video/day.pss");
// their LBAs are the image's, so where a file lies changes seeks and the CAV rate as on hardware.
// Reads go through libcdio's libiso9660, so this target is not part of the portable model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "iop/sector_source.hpp"

namespace vbim::streams {

class IsoDisc final : public iop::SectorSource {
 public:
  // Opens and checks the image. Throws iop::DiscError when it is missing, unreadable, not ISO 9660
  // (no primary volume descriptor at LBA 16) or truncated (shorter than its volume size).
  explicit IsoDisc(std::string path);
  ~IsoDisc() override;
  IsoDisc(const IsoDisc&) = delete;
  IsoDisc& operator=(const IsoDisc&) = delete;

  std::int64_t sectorCount() const override { return sectors_; }
  iop::SectorReadResult read(std::int64_t lba, iop::SectorSpan out) override;
  std::optional<iop::DiscFile> find(std::string_view path) const override;
  std::string describe() const override { return path_; }
  // Every file on the volume, in directory order (depth first), named as sceCdSearchFile names them
  // ("\\DATA\\DAY.VBI;1"), with its LBA and length.
  std::vector<iop::DiscFile> files() const;

  // "\\VIDEO\\DAY.PSS;1" -> "/video/day.pss": the form libiso9660's translated lookup expects.
  static std::string normalisePath(std::string_view path);

 private:
  std::string path_;
  void* iso_ = nullptr;  // iso9660_t*, opaque here so users need no libcdio headers
  std::int64_t sectors_ = 0;
};

}  // namespace vbim::streams
