#include "streams/disc/iso9660_records.hpp"

#include <cstring>

namespace vbim::streams::iso9660 {

namespace {

std::string at(std::int64_t lba, std::size_t offset) {
  return "LBA " + std::to_string(lba) + " byte " + std::to_string(offset);
}

// Both-endian numbers (ECMA-119, 4th edition, sections 7.2.3 and 7.3.3) hold the value twice, least
// significant byte first and then most significant byte first. A writer that disagrees with itself
// is damaged, so both halves must agree rather than one being trusted.
std::uint32_t bothEndian32(Sector s, std::size_t offset, std::int64_t lba, const char* field) {
  const std::uint32_t le = static_cast<std::uint32_t>(s[offset]) | static_cast<std::uint32_t>(s[offset + 1]) << 8 |
                           static_cast<std::uint32_t>(s[offset + 2]) << 16 |
                           static_cast<std::uint32_t>(s[offset + 3]) << 24;
  const std::uint32_t be = static_cast<std::uint32_t>(s[offset + 4]) << 24 |
                           static_cast<std::uint32_t>(s[offset + 5]) << 16 |
                           static_cast<std::uint32_t>(s[offset + 6]) << 8 | static_cast<std::uint32_t>(s[offset + 7]);
  if (le != be) {
    throw iop::DiscError(std::string(field) + " at " + at(lba, offset) + ": its little-endian half " +
                         std::to_string(le) + " and big-endian half " + std::to_string(be) +
                         " disagree (ECMA-119 both-endian field)");
  }
  return le;
}

std::uint16_t bothEndian16(Sector s, std::size_t offset, std::int64_t lba, const char* field) {
  const auto le = static_cast<std::uint16_t>(s[offset] | s[offset + 1] << 8);
  const auto be = static_cast<std::uint16_t>(s[offset + 2] << 8 | s[offset + 3]);
  if (le != be) {
    throw iop::DiscError(std::string(field) + " at " + at(lba, offset) + ": its little-endian half " +
                         std::to_string(le) + " and big-endian half " + std::to_string(be) +
                         " disagree (ECMA-119 both-endian field)");
  }
  return le;
}

// Byte offsets in the primary volume descriptor (ECMA-119, 4th edition, section 8.4; the standard
// counts byte positions from 1, these from 0).
constexpr std::size_t kVolumeSpaceSize = 80;    // section 8.4.8
constexpr std::size_t kLogicalBlockSize = 128;  // section 8.4.12
constexpr std::size_t kRootRecord = 156;        // section 8.4.18
constexpr std::size_t kRootRecordBytes = 34;    // a record with a 1-byte identifier
constexpr std::size_t kOnlyBlockSize = iop::kSectorBytes;

}  // namespace

std::int64_t DirectoryRecord::sectors() const {
  return (bytes + static_cast<std::int64_t>(iop::kSectorBytes) - 1) / static_cast<std::int64_t>(iop::kSectorBytes);
}

DescriptorKind descriptorKind(Sector sector) {
  // ECMA-119, 4th edition, section 8.1: type (byte 0), "CD001" (bytes 1-5), version 1 (byte 6).
  if (std::memcmp(sector.data() + 1, "CD001", 5) != 0 || sector[6] != 1) return DescriptorKind::NotDescriptor;
  if (sector[0] == 1) return DescriptorKind::Primary;
  if (sector[0] == 255) return DescriptorKind::Terminator;
  return DescriptorKind::Other;
}

PrimaryVolume parsePrimaryVolume(Sector sector, std::int64_t lba) {
  const std::uint16_t blockSize = bothEndian16(sector, kLogicalBlockSize, lba, "logical block size");
  if (blockSize != kOnlyBlockSize) {
    throw iop::DiscError("logical block size " + std::to_string(blockSize) + " at " + at(lba, kLogicalBlockSize) +
                         ", expected 2048 (the only block size a DVD image uses)");
  }
  PrimaryVolume v;
  v.sectors = bothEndian32(sector, kVolumeSpaceSize, lba, "volume space size");
  const auto root = parseRecord(sector, kRootRecord, kRootRecord + kRootRecordBytes, lba);
  if (!root || root->length != kRootRecordBytes || !root->directory) {
    throw iop::DiscError("root directory record at " + at(lba, kRootRecord) +
                         ": expected a directory record of 34 bytes (ECMA-119, 4th edition, section 8.4.18)");
  }
  v.root = *root;
  return v;
}

std::optional<DirectoryRecord> parseRecord(Sector sector, std::size_t offset, std::size_t used, std::int64_t lba) {
  if (used > sector.size()) used = sector.size();
  if (offset >= used || sector[offset] == 0) return std::nullopt;  // padding to the next sector (6.8.1.1)
  // ECMA-119, 4th edition, section 9.1: length (byte 0), extended attribute record length (1), extent
  // (2-9), data length (10-17), flags (25), file unit size (26), interleave gap (27), identifier
  // length (32), identifier (33...).
  DirectoryRecord r;
  r.length = sector[offset];
  if (r.length < kRecordHeaderBytes) {
    throw iop::DiscError("directory record at " + at(lba, offset) + ": length " + std::to_string(r.length) +
                         " is shorter than a record's 33-byte fixed part");
  }
  if (offset + r.length > used) {
    throw iop::DiscError("directory record at " + at(lba, offset) + ": its " + std::to_string(r.length) +
                         " bytes run past byte " + std::to_string(used) +
                         ", the end of the directory's data in this sector (records never cross a sector)");
  }
  const std::size_t idBytes = sector[offset + 32];
  if (idBytes == 0 || kRecordHeaderBytes + idBytes > r.length) {
    throw iop::DiscError("directory record at " + at(lba, offset) + ": an identifier of " + std::to_string(idBytes) +
                         " bytes does not fit a record of " + std::to_string(r.length) + " bytes (expected 1 to " +
                         std::to_string(r.length - kRecordHeaderBytes) + ")");
  }
  // The extended attribute record, when there is one, fills the extent's first blocks and the data
  // follows it (ECMA-119, 4th edition, section 9.1.2): `extent` is where the data starts.
  const std::int64_t attributeBlocks = sector[offset + 1];
  r.extent = static_cast<std::int64_t>(bothEndian32(sector, offset + 2, lba, "extent location")) + attributeBlocks;
  r.bytes = bothEndian32(sector, offset + 10, lba, "data length");
  const std::uint8_t flags = sector[offset + 25];
  r.directory = (flags & 0x02) != 0;
  r.multiExtent = (flags & 0x80) != 0;
  r.interleaved = sector[offset + 26] != 0 || sector[offset + 27] != 0;
  r.identifier.assign(reinterpret_cast<const char*>(sector.data() + offset + kRecordHeaderBytes), idBytes);
  return r;
}

std::string extentProblem(const DirectoryRecord& record, std::int64_t volumeSectors) {
  if (record.extent + record.sectors() <= volumeSectors) return {};
  return "at LBA " + std::to_string(record.extent) + " runs past the end of the volume (" +
         std::to_string(volumeSectors) + " sectors)";
}

std::string nameKey(std::string_view identifier) {
  std::string r;
  for (char c : identifier) {
    if (c == ';') break;  // ";1": the file version (ECMA-119, 4th edition, section 7.5.1)
    r.push_back(c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c);
  }
  if (!r.empty() && r.back() == '.') r.pop_back();  // "FILE." : a name with no extension
  return r;
}

}  // namespace vbim::streams::iso9660
