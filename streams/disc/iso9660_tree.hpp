// The directory tree of an ISO 9660 volume (ECMA-119, 4th edition, sections 6.8 and 9.1), walked
// through a sector reader so that it can be tested on sectors in memory. Every directory's extent is
// checked against the volume before it is read, at most 8 levels are followed (section 6.8.2.1),
// and files() reads no directory extent twice, so a damaged tree that loops or links one directory
// many times costs at most one pass over the volume. Messages name no image: IsoDisc puts the
// image's name in front.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "iop/sector_source.hpp"
#include "streams/disc/iso9660_records.hpp"

namespace vbim::streams::iso9660 {

// Reads logical sector `lba` into `out`, or throws iop::DiscError saying why it cannot.
using SectorReader = std::function<void(std::int64_t lba, iop::SectorSpan out)>;

class DirectoryTree {
 public:
  DirectoryTree(SectorReader read, PrimaryVolume volume);

  // Every file, depth first in record order, named as sceCdSearchFile names them ("\\DATA\\DAY.VBI;1":
  // directories as recorded, file names in upper case with ";1" added when they have no version).
  // Left out, because the drive model streams a file from one contiguous extent: multi-extent and
  // interleaved files; directories below level 8; a directory whose extent overlaps one already
  // listed (a loop or a repeated link). Throws iop::DiscError for a damaged record or a file or
  // directory running past the end of the volume, naming it.
  std::vector<iop::DiscFile> files() const;

  // The file `path` names ("/video/day.pss", as IsoDisc::normalisePath gives it), matched by nameKey()
  // per level, or nullopt when there is none (or it is a directory, or lies below level 8). The
  // DiscFile's path is left empty. Throws iop::DiscError naming `shownPath` when the file runs past
  // the end of the volume or is multi-extent or interleaved, and for damaged directories on the way.
  std::optional<iop::DiscFile> find(std::string_view path, std::string_view shownPath) const;

 private:
  // The records of `dir` (shown as `name` in messages) without "." and "..", in order.
  std::vector<DirectoryRecord> readDirectory(const DirectoryRecord& dir, std::string_view name) const;

  SectorReader read_;
  PrimaryVolume volume_;
};

}  // namespace vbim::streams::iso9660
