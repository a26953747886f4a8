// The PNG of png_encoder.hpp's level 0 (rows unfiltered, stored deflate blocks) written without
// libpng, byte for byte what libpng 1.6.39 and zlib 1.2.13 write at png_encoder.cpp's settings.
// Why: at level 0 the work is copying the rows and two checksums, and libpng has no hook for its
// checksums: it calls zlib's crc32 and zlib's deflate computes the Adler-32, both a byte at a time
// (about half the picture thread's CPU before the file's write; issue #31). Here the rows go once,
// straight into the file's buffer, and libdeflate's CRC-32 and Adler-32 (PCLMUL and AVX2 where the
// CPU has them, chosen at run time) check them. The bytes are the same, so a reader cannot tell
// (tests/imageio/stored_png_test.cpp compares the two writers over many shapes).
#pragma once

#include <cstddef>
#include <cstdint>

#include "imageio/image_view.hpp"

namespace vbim::imageio {

// `channels` says which samples of `image` the PNG holds (image_view.hpp): RgbOfRgba needs a
// 4-channel image and writes an RGB PNG, the bytes writeStoredPng writes for the packed RGB samples.

// Whether writeStoredPng can write `image` (8-bit, 1 to 4 channels, a positive size): false past
// libpng's default limit of a million pixels a side, where libpng refuses the picture, and where
// png_encoder.cpp's compression buffer (one IDAT chunk) would pass 2^31 - 1 bytes and libpng would
// split the data over several IDAT chunks. png_encoder.cpp leaves those to libpng.
bool fitsStoredPng(ImageView<std::uint8_t> image, FileChannels channels = FileChannels::AsGiven);

// The size of the PNG writeStoredPng writes (fitsStoredPng(image) must hold).
std::size_t storedPngSize(ImageView<std::uint8_t> image, FileChannels channels = FileChannels::AsGiven);

// Writes the PNG to `out`, storedPngSize(image) bytes: the signature, IHDR, sRGB (perceptual), one
// IDAT chunk (a zlib stream of stored blocks: every row as filter byte 0 then its samples), IEND.
// The samples are read once: each piece of the rows is packed (RgbOfRgba) or copied into `out` and
// both checksums taken over it while it is in the core's first-level cache.
void writeStoredPng(ImageView<std::uint8_t> image, std::uint8_t* out, FileChannels channels = FileChannels::AsGiven);

}  // namespace vbim::imageio
