// The disc a command was given and the VBIM stream on it: a bare stream file (placed as `vbim play`
// always placed it) or an ISO 9660 image, told apart by the image's volume descriptor, not by the
// file name. On an image the stream is the file named with --file ("\\DATA\\DAY.VBI;1", found like
// sceCdSearchFile) or else the one VBIM stream on it; its LBAs are the image's, so the drive model
// seeks to where the file really lies.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "iop/sector_source.hpp"

namespace vbim::streams {

struct StreamDisc {
  std::shared_ptr<iop::SectorSource> disc;
  iop::DiscFile file;
  bool image = false;  // an ISO 9660 image (false: a bare stream file)
};

// True when `path` holds an ISO 9660 volume descriptor ("CD001", ECMA-119 8.1) at LBA 16.
bool isIsoImage(const std::filesystem::path& path);

// Opens `path` as a disc and picks the stream on it. `file` (empty: the default) names a file on an
// image; for a bare stream file it must be empty. Throws iop::DiscError naming the image and, when
// the file is not found or several VBIM streams are on the image, the candidates.
StreamDisc openStreamDisc(const std::string& path, const std::string& file = {});

// The bytes of `file` on `disc` (for the commands that read a whole stream: info, decode).
// Throws iop::DiscError naming the disc and the LBA when a sector cannot be read.
std::vector<std::uint8_t> readDiscFile(iop::SectorSource& disc, const iop::DiscFile& file);

// The stream's authoring record (streams/record_packs.hpp), read from the sectors after its
// video, or nullopt when it has none (or is not a VBIM stream). Reads at most 256 sectors.
std::optional<std::string> readAuthoringRecord(iop::SectorSource& disc, const iop::DiscFile& file);

}  // namespace vbim::streams
