// libavcodec's MPEG-2 decoder, as the reference the tests and tools compare against: one coded
// picture (as the reader reassembles it) in, RGBA8 or the YCbCr planes out.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

#include "runtime/image.hpp"

struct AVCodecContext;
struct AVFrame;
struct AVPacket;

namespace vbim::streams {

class Mpeg2Decoder {
 public:
  Mpeg2Decoder();
  ~Mpeg2Decoder();
  Mpeg2Decoder(const Mpeg2Decoder&) = delete;
  Mpeg2Decoder& operator=(const Mpeg2Decoder&) = delete;

  // Decodes one intra picture (sequence header included). Throws AuthoringError on a decode error.
  Yuv420Image decodeYuv(std::span<const std::uint8_t> picture);
  // The same, converted with BT.601 limited range -> full-range RGB (alpha 0x80).
  Rgba8Image decodeRgba(std::span<const std::uint8_t> picture);
  // The picture type of the last decoded picture ('I', 'P', 'B').
  char lastPictureType() const { return lastType_; }

 private:
  AVCodecContext* ctx_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* pkt_ = nullptr;
  char lastType_ = '?';
};

// PSNR in dB over R, G, B of two same-size images (inf when identical).
double psnrRgb(const Rgba8Image& a, const Rgba8Image& b);
// PSNR in dB of each plane (Y, Cb, Cr) of two same-size images.
struct PlanePsnr {
  double y = 0, cb = 0, cr = 0;
  double min() const { return std::min(y, std::min(cb, cr)); }
};
PlanePsnr psnrYuv(const Yuv420Image& a, const Yuv420Image& b);

}  // namespace vbim::streams
