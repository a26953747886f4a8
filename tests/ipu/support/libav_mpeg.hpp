// Test and benchmark support: makes intra-only MPEG-1/2 elementary streams with libavcodec's
// encoders (so no large files are committed) and decodes them with libavcodec for comparison.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ipu/elementary_stream.hpp"
#include "runtime/image.hpp"

namespace vbim::ipu::testing {

// kPan: a smooth texture panned by 1.5 samples right and 0.75 lines down per frame, so motion
// vectors are non-trivial and half-sample.
enum class Content { kSmooth, kBusy, kNoise, kInterlaced, kLightmap, kPattern, kPan };

struct EncodeOptions {
  int width = 64;
  int height = 48;
  int frames = 2;
  int gopSize = 1;            // 1: intra only; more: P pictures follow the I picture
  int bFrames = 0;            // B pictures between references (max_b_frames)
  bool interlacedMe = false;  // field motion estimation (AV_CODEC_FLAG_INTERLACED_ME), top field first
  int quantiser = 5;          // fixed qscale 1..31 (frame->quality, docs/dependencies.md#fixed-quantiser)
  bool mpeg1 = false;
  bool intraVlc = false;  // B.15
  bool alternateScan = false;
  bool nonLinearQuant = false;
  int dcPrecision = 0;  // 0..3 = 8..11 bits
  bool customMatrix = false;
  bool customInterMatrix = false;  // a non-intra matrix of its own too (P and B pictures)
  bool interlacedDct = false;      // field DCT decisions (progressive_sequence = 0)
  Content content = Content::kSmooth;
  std::uint32_t seed = 1;
  std::string describe() const;
};

// Deterministic synthetic frames.
std::vector<Yuv420Image> makeFrames(const EncodeOptions& o);
// Encodes frames to an elementary stream (intra only with gop 1; GOPs with P and B pictures otherwise). Throws
// std::runtime_error on failure.
std::vector<std::uint8_t> encodeIntra(const EncodeOptions& o, const std::vector<Yuv420Image>& frames);
inline std::vector<std::uint8_t> encodeIntra(const EncodeOptions& o) {
  return encodeIntra(o, makeFrames(o));
}
// The pictures of encodeIntra(o), each its own bytes (an access unit: headers .. last slice), in
// stream order. Callers link vbim_ipu (splitAccessUnits).
inline std::vector<std::vector<std::uint8_t>> encodePictures(const EncodeOptions& o) {
  const std::vector<std::uint8_t> es = encodeIntra(o);
  std::vector<std::vector<std::uint8_t>> out;
  for (const AccessUnit& au : splitAccessUnits(es)) {
    out.emplace_back(es.begin() + static_cast<std::ptrdiff_t>(au.offset),
                     es.begin() + static_cast<std::ptrdiff_t>(au.offset + au.size));
  }
  return out;
}

// libavcodec's decode of an elementary stream, threads = 1. idctAlgo: an FF_IDCT_* value.
std::vector<Yuv420Image> decodeWithLibav(const std::vector<std::uint8_t>& es, bool mpeg1, int idctAlgo = 0);

// Planes compared: how many samples differ and by how much.
struct PlaneDiff {
  std::size_t samples = 0;
  std::size_t different = 0;
  int maxAbs = 0;
  double identicalFraction() const { return samples ? 1.0 - static_cast<double>(different) / samples : 1.0; }
};
PlaneDiff compare(const Yuv420Image& a, const Yuv420Image& b);

}  // namespace vbim::ipu::testing
