#include "streams/disc/iso_disc.hpp"

#include <array>
#include <filesystem>
#include <system_error>

#include "streams/disc/iso9660_records.hpp"
#include "streams/disc/iso9660_tree.hpp"

namespace vbim::streams {

namespace {

// Real volume descriptor sets hold a handful of descriptors (primary, boot record, supplementary,
// terminator); a set that goes on longer without a terminator is not one worth scanning.
constexpr std::int64_t kMaxDescriptors = 32;

// Runs `f`, putting the image's name in front of the DiscError the ISO 9660 reader throws.
template <typename F>
auto naming(const std::string& image, F&& f) {
  try {
    return f();
  } catch (const iop::DiscError& e) {
    throw iop::DiscError(image + ": " + e.what());
  }
}

}  // namespace

std::string IsoDisc::normalisePath(std::string_view path) {
  std::string r;
  for (char c : path) {
    if (c == ';') break;  // version suffix
    if (c == '\\') c = '/';
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    r.push_back(c);
  }
  if (r.empty() || r.front() != '/') r.insert(r.begin(), '/');
  if (r.size() > 1 && r.back() == '.') r.pop_back();  // "FILE." (no extension) as ISO names it
  return r;
}

IsoDisc::IsoDisc(std::string path) : path_(std::move(path)) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) throw iop::DiscError(path_ + ": no such disc image");
  if (std::filesystem::is_directory(path_, ec)) throw iop::DiscError(path_ + ": is a directory, expected an ISO image");
  const auto bytes = std::filesystem::file_size(path_, ec);
  if (ec) throw iop::DiscError(path_ + ": cannot read its size: " + ec.message());
  if (!file_.open(path_)) throw iop::DiscError(path_ + ": cannot open for reading");
  // The volume descriptors start at LBA 16, after the system area (ECMA-119, 4th edition, section
  // 6.2.1): an image must reach past it.
  constexpr std::uint64_t kPvdEnd = 17 * iop::kSectorBytes;
  if (bytes < kPvdEnd) {
    throw iop::DiscError(path_ + ": " + std::to_string(bytes) + " bytes is too short for ISO 9660: the primary " +
                         "volume descriptor is at byte offset 32768 (LBA 16)");
  }
  // The volume descriptor set: the primary volume descriptor, maybe others, then a terminator
  // (ECMA-119, 4th edition, sections 8.1, 8.3 and 8.4).
  const auto imageSectors = static_cast<std::int64_t>(bytes / iop::kSectorBytes);
  std::optional<iso9660::PrimaryVolume> pvd;
  std::array<std::uint8_t, iop::kSectorBytes> sector{};
  for (std::int64_t lba = iso9660::kFirstDescriptorLba;
       !pvd && lba < imageSectors && lba < iso9660::kFirstDescriptorLba + kMaxDescriptors && readSector(lba, sector);
       ++lba) {
    const iso9660::DescriptorKind kind = iso9660::descriptorKind(sector);
    if (kind == iso9660::DescriptorKind::Primary) {
      pvd = naming(path_, [&] { return iso9660::parsePrimaryVolume(sector, lba); });
    } else if (kind != iso9660::DescriptorKind::Other) {
      break;
    }
  }
  if (!pvd) throw iop::DiscError(path_ + ": no ISO 9660 primary volume descriptor at LBA 16 (byte offset 32768)");
  sectors_ = pvd->sectors;
  const std::uint64_t need = static_cast<std::uint64_t>(sectors_) * iop::kSectorBytes;
  if (sectors_ <= 0 || bytes < need) {
    throw iop::DiscError(path_ + ": truncated: the volume holds " + std::to_string(sectors_) + " sectors (" +
                         std::to_string(need) + " bytes) but the image has " + std::to_string(bytes) +
                         " bytes; the first missing sector is LBA " + std::to_string(bytes / iop::kSectorBytes));
  }
  if (const std::string why = iso9660::extentProblem(pvd->root, sectors_); !why.empty()) {
    throw iop::DiscError(path_ + ": the root directory " + why + ": damaged image");
  }
  tree_ = std::make_unique<iso9660::DirectoryTree>(
      [this](std::int64_t lba, iop::SectorSpan out) {
        if (!readSector(lba, out)) {
          throw iop::DiscError("cannot read LBA " + std::to_string(lba) + " (byte offset " +
                               std::to_string(lba * static_cast<std::int64_t>(iop::kSectorBytes)) + ")");
        }
      },
      *pvd);
}

IsoDisc::~IsoDisc() = default;

bool IsoDisc::readSector(std::int64_t lba, iop::SectorSpan out) const {
  const std::scoped_lock lock(fileMutex_);
  return file_.read(lba * static_cast<std::int64_t>(iop::kSectorBytes), out);
}

iop::SectorReadResult IsoDisc::read(std::int64_t lba, iop::SectorSpan out) {
  if (lba < 0 || lba >= sectors_) {
    return {false, path_ + ": LBA " + std::to_string(lba) + " is outside the volume (0.." +
                       std::to_string(sectors_ - 1) + ")"};
  }
  if (!readSector(lba, out)) {
    return {false, path_ + ": read of LBA " + std::to_string(lba) + " (byte offset " +
                       std::to_string(lba * static_cast<std::int64_t>(iop::kSectorBytes)) + ") failed"};
  }
  return {};
}

std::vector<iop::DiscFile> IsoDisc::files() const {
  return naming(path_, [&] { return tree_->files(); });
}

std::optional<iop::DiscFile> IsoDisc::find(std::string_view path) const {
  // sceCdSearchFile names are upper case with a version ("\\VIDEO\\DAY.PSS;1"); mastering tools
  // differ on whether they record the version, so names are compared without it and case.
  auto f = naming(path_, [&] { return tree_->find(normalisePath(path), path); });
  if (f) f->path = std::string(path);
  return f;
}

}  // namespace vbim::streams
