// How close a re-encoded stream (a sweep plan's `qscales`, `bitrates`, `gops`) is to the frames it
// was made from: its lightmap pictures are decoded by the IPU model, as the player decodes them
// (streams/decode/), and each frame's luma is compared with the luma the encoder took
// (streams::transcodeStream's `sources`). Luma, because the encoder's loss is in YCbCr: an RGB
// comparison would add the two colour conversions' rounding to it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "runtime/image.hpp"
#include "sweep/profile_run.hpp"

namespace vbim::sweep {

// PSNR of one frame's luma in dB: 10 log10(255^2 / MSE), from an integer sum of squared
// differences; kIdenticalPsnrDb when the two are identical.
inline constexpr double kIdenticalPsnrDb = 100.0;
double lumaPsnr(std::span<const std::uint8_t> a, std::size_t aStride, std::span<const std::uint8_t> b,
                std::size_t bStride, int width, int height);

// Decodes the lightmap (stream 0xE0) of `reencoded` and compares frame g (display order over all
// variants) with sources[g]. Throws vbim::Error naming `name` when the stream does not decode or its
// frames are not the sources' in number or size.
StreamQuality measureStreamQuality(std::span<const std::uint8_t> reencoded, const std::string& name,
                                   const std::vector<Yuv420Image>& sources);

}  // namespace vbim::sweep
