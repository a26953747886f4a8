// Writes an ISO 9660 image holding given files, as a game's disc would hold its streams: made by
// xorriso (Debian package xorriso; `xorriso -as mkisofs`, ECMA-119 level 1 names), so the image is
// what any mastering tool would write, and reads back through IsoDisc (iso_disc.hpp). The image is
// reproducible: its volume and file dates come from SOURCE_DATE_EPOCH (2000-01-01 when unset), not
// from the clock or the files' times, so the same files give the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vbim::streams {

struct IsoEntry {
  std::string discPath;            // as sceCdSearchFile names it: "\\DATA\\DAY.VBI;1" (8.3 names, upper case)
  std::filesystem::path hostFile;  // the bytes to put there
};

// Empty when `discPath` is a path ISO 9660 level 1 holds as given ("\\DATA\\DAY.VBI;1",
// "/data/day.vbi": directories and names of 1-8 characters A-Z 0-9 _, an extension of up to 3, at most
// 8 levels, ECMA-119 7.5 and 6.8.2.1); otherwise what is wrong with it.
std::string level1PathProblem(const std::string& discPath);

// Writes `image` (under a temporary name, renamed when complete) with `files`, volume id `volumeId`.
// Throws iop::DiscError naming the image when a disc path is not one level 1 holds (before any
// work), when xorriso is missing or fails (with its message), or when a file is not where its disc
// path says once the image is read back.
void writeIsoImage(const std::filesystem::path& image, const std::vector<IsoEntry>& files,
                   const std::string& volumeId = "VBIM");

}  // namespace vbim::streams
