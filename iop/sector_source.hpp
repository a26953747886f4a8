// The disc as the drive model sees it: numbered 2048-byte user sectors (DVD data sectors,
// docs/hardware.md#dvd-drive) and the files that lie on them. The model reads only through this interface, so it never
// depends on how an image is stored: a bare stream file (iop/file_disc.hpp), an ISO 9660 image
// (streams/disc/), or sectors in memory (tests).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "iop/error.hpp"

namespace vbim::iop {

inline constexpr std::size_t kSectorBytes = 2048;  // DVD user data per sector (T-CDVD)
using SectorSpan = std::span<std::uint8_t, kSectorBytes>;

// Where a file lies: its first logical sector (LBA = LSN on a single-layer DVD) and its length.
struct DiscFile {
  std::string path;
  std::int64_t lba = 0;
  std::int64_t bytes = 0;
  std::int64_t sectors() const { return (bytes + static_cast<std::int64_t>(kSectorBytes) - 1) / kSectorBytes; }
};

struct SectorReadResult {
  bool ok = true;
  std::string error;  // host-side failure (I/O error); names the image and the LBA
};

class SectorSource {
 public:
  virtual ~SectorSource() = default;
  // Sectors on the disc: reading at or past this LSN is "end of media" (error 0x32, P-CDVD).
  virtual std::int64_t sectorCount() const = 0;
  // Reads one 2048-byte user sector. lba must be in [0, sectorCount()).
  virtual SectorReadResult read(std::int64_t lba, SectorSpan out) = 0;
  // Finds a file by path, as sceCdSearchFile does ("\\VIDEO\\DAY.PSS;1" or "video/day.pss").
  // Returns nothing when the disc has no such file.
  virtual std::optional<DiscFile> find(std::string_view path) const = 0;
  // The image's name for messages ("day.pss (bare stream at LBA 100000)").
  virtual std::string describe() const = 0;
};

// Finds `path` or throws a DiscError naming the image and the path.
inline DiscFile requireFile(const SectorSource& disc, std::string_view path) {
  auto f = disc.find(path);
  if (!f) throw DiscError(disc.describe() + ": no file '" + std::string(path) + "' on the disc");
  return *f;
}

}  // namespace vbim::iop
