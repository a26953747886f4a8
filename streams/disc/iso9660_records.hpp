// ISO 9660 structures read from byte spans (ECMA-119, 4th edition): the volume descriptors and the
// directory records. Every field is checked before anything follows it, so a damaged or hostile
// image gives an iop::DiscError saying where (LBA, byte) and what was expected, never a read out of
// bounds. Pure functions on bytes: IsoDisc (iso_disc.hpp) does the file I/O and walks the tree
// (iso9660_tree.hpp). The messages name no image; the caller puts the image's name in front.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "iop/sector_source.hpp"

namespace vbim::streams::iso9660 {

using Sector = std::span<const std::uint8_t, iop::kSectorBytes>;

// The volume descriptor set follows the system area, logical sectors 0-15 (ECMA-119, 4th edition,
// section 6.2.1), so it starts at LBA 16.
inline constexpr std::int64_t kFirstDescriptorLba = 16;
// ECMA-119, 4th edition, section 6.8.2.1: at most 8 levels of directories, the root being level 1.
inline constexpr int kMaxDirectoryLevels = 8;
// ECMA-119, 4th edition, section 9.1: a directory record is 33 bytes plus its identifier.
inline constexpr std::size_t kRecordHeaderBytes = 33;

// One directory record (ECMA-119, 4th edition, section 9.1), checked for its own consistency.
struct DirectoryRecord {
  std::size_t length = 0;    // bytes the record takes in its sector (byte 0)
  std::int64_t extent = 0;   // LBA of the extent's first sector (bytes 2-9)
  std::int64_t bytes = 0;    // data length (bytes 10-17)
  bool directory = false;    // flags bit 1 (byte 25)
  bool multiExtent = false;  // flags bit 7: the file goes on in the next record's extent
  bool interleaved = false;  // file unit size (byte 26) or interleave gap (byte 27) non-zero
  std::string identifier;    // bytes 33...: as recorded; "\0" is the directory itself, "\1" its parent

  bool selfOrParent() const { return identifier.size() == 1 && (identifier[0] == '\0' || identifier[0] == '\1'); }
  std::int64_t sectors() const;
};

// What a sector of the volume descriptor set holds (ECMA-119, 4th edition, section 8.1).
enum class DescriptorKind {
  NotDescriptor,  // no "CD001" standard identifier, or a version other than 1
  Primary,        // type 1 (section 8.4)
  Terminator,     // type 255 (section 8.3)
  Other,          // boot record, supplementary or partition descriptor: skipped
};
DescriptorKind descriptorKind(Sector sector);

struct PrimaryVolume {
  std::int64_t sectors = 0;  // volume space size
  DirectoryRecord root;
};

// Reads the primary volume descriptor in `sector` (at `lba`, for messages), which descriptorKind()
// called primary. Throws iop::DiscError when the logical block size is not 2048, a both-endian
// field's halves disagree, or the root directory record is not a directory record of 34 bytes.
PrimaryVolume parsePrimaryVolume(Sector sector, std::int64_t lba);

// The directory record at byte `offset` of `sector` (the sector at `lba`, for messages), of which only
// the first `used` bytes belong to the directory. nullopt when the length byte is zero: the rest of
// the sector is padding and the next record starts at the next sector (ECMA-119, 4th edition, section
// 6.8.1.1). Throws iop::DiscError when the record is shorter than 33 bytes plus its identifier, does
// not fit in the sector, or a both-endian field's halves disagree.
std::optional<DirectoryRecord> parseRecord(Sector sector, std::size_t offset, std::size_t used, std::int64_t lba);

// Empty when `record`'s extent lies inside a volume of `volumeSectors`; otherwise what is wrong
// ("at LBA 900 runs past the end of the volume (120 sectors)").
std::string extentProblem(const DirectoryRecord& record, std::int64_t volumeSectors);

// The key names are compared by, as sceCdSearchFile matches them: lower case, without the
// ";version", and without a trailing '.' ("DAY.PSS;1" and "day.pss" -> "day.pss", "FILE.;1" -> "file").
std::string nameKey(std::string_view identifier);

}  // namespace vbim::streams::iso9660
