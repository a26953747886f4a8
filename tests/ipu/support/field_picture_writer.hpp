// Test support: writes what libavcodec's encoder never emits, so the decoder's field pictures and
// dual-prime prediction can be checked against libmpeg2: P pictures (field pictures, and frame
// pictures with dual prime) whose macroblocks use random legal field, 16x8 and dual-prime
// predictions, skips and small residuals, appended to an interlaced I frame made by libavcodec.
// A bitstream writer of ISO/IEC 13818-2 §6.2 for these few syntax elements only.
#pragma once

#include <cstdint>
#include <vector>

namespace vbim::ipu::testing {

struct FieldStreamOptions {
  int width = 96;  // multiples of 16; the height a multiple of 32
  int height = 64;
  bool fieldPictures = true;        // P field pairs (top then bottom); false: P frame pictures
  bool dualPrime = true;            // dual prime among the predictions (only these pictures: no B pictures follow)
  int pictures = 2;                 // P frames appended
  bool concealmentVectors = false;  // concealment_motion_vectors, with intra macroblocks among the P ones
  std::uint32_t seed = 1;
};

// An elementary stream: sequence header and extension, an I frame (libavcodec, interlaced), the P
// pictures, sequence_end_code.
std::vector<std::uint8_t> makeFieldStream(const FieldStreamOptions& o);

}  // namespace vbim::ipu::testing
