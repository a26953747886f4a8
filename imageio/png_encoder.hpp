// PNG files at a chosen zlib level, for pictures written in bulk (`vbim play`'s and `vbim
// replay`'s frames while a play runs, issue #31; every picture of `vbim decode`), by libpng's full API: the simplified
// API of png_writer.hpp offers no level. libpng's default (zlib level 6, every row filter tried) took ~18 ms for a
// 256x256 lightmap and its 128x64 sky, ten times the whole fault-free play of a minute; level 0 stores the rows
// uncompressed (2.5x the bytes) in a small fraction of that, and levels 1 to 9 compress (level 1: about libpng's
// default size in a third of its time). docs/player.md, "Saving frames", has the table (bench/player/image_share.sh).
// The file has what libpng's simplified API writes: IHDR, sRGB, one IDAT, IEND.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "imageio/image_view.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

inline constexpr int kMaxPngLevel = 9;  // zlib's highest

// The `--png-level` of `vbim play` and `vbim decode`, checked before a run writes anything: throws
// vbim::Error (bad input) naming the option and the range unless 0 <= level <= kMaxPngLevel.
void checkPngLevelOption(int level);

// The PNG bytes of 8-bit grey (1 channel), grey + alpha (2), RGB (3) or RGBA (4) samples, tagged
// sRGB. `level` 0: stored deflate blocks, every row unfiltered (written by stored_png.hpp, libpng's
// bytes without libpng); 1 to 9: zlib's level of that number, every row filtered Up. `channels`:
// the samples as given, or an RGB PNG of a 4-channel image's first three (image_view.hpp). Throws
// ImageIoError naming `name` for a bad shape or level, or what libpng reported.
std::vector<std::uint8_t> encodePng(ImageView<std::uint8_t> image, int level, const std::filesystem::path& name,
                                    FileChannels channels = FileChannels::AsGiven);

// encodePng's bytes, always by libpng: at level 0 encodePng writes the same bytes itself
// (stored_png.hpp), and is tested against this.
std::vector<std::uint8_t> encodePngWithLibpng(ImageView<std::uint8_t> image, int level,
                                              const std::filesystem::path& name);

// encodePng's bytes written to `path`, by default under a temporary name and renamed into place
// (replace_file.hpp: `placement`); libpng's and zlib's memory is kept per thread for the next
// picture. Throws ImageIoError naming the file.
void writePngAtLevel(const std::filesystem::path& path, ImageView<std::uint8_t> image, int level,
                     FileChannels channels = FileChannels::AsGiven,
                     FilePlacement placement = FilePlacement::TemporaryThenRename);

}  // namespace vbim::imageio
