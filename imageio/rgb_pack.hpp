// RGB of RGBA: the first three bytes of each 4-byte texel, packed (issue #31: vbim play's opaque
// pictures are RGB files). One function for every writer that drops the alpha: stored_png.cpp as it
// writes a PNG's rows, png_encoder.cpp before libpng, texel_files.cpp before an EXR.
#pragma once

#include <cstddef>
#include <cstdint>

namespace vbim::imageio {

// Writes the R, G and B of `texels` texels at `rgba` to `rgb` (3 * texels bytes). `rgb` may be
// `rgba` itself (packing in place) or any buffer that does not overlap it. No SIMD: Highway's
// LoadInterleaved4 + StoreInterleaved3 (AVX-512 on the build machine) made no difference to the
// picture thread's CPU (packing 6.5 % of it against 6.8 %, perf of 20 demo plays each, 2026-12-05):
// the time is the first read of texels another core wrote, not the shuffling.
void packRgbOfRgba(const std::uint8_t* rgba, std::size_t texels, std::uint8_t* rgb);

// The byte-at-a-time reference packRgbOfRgba is tested against.
void packRgbOfRgbaReference(const std::uint8_t* rgba, std::size_t texels, std::uint8_t* rgb);

}  // namespace vbim::imageio
