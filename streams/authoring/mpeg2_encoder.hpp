// One intra-only MPEG-2 video encoder (libavcodec): RGBA8 frames in, one coded picture per frame out.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/image.hpp"
#include "streams/authoring/libav.hpp"
#include "streams/descriptor.hpp"

namespace vbim::streams {

struct EncoderSettings {
  int qscale = 3;            // fixed quantiser_scale 1..31 (used when bitrate == 0)
  std::int64_t bitrate = 0;  // target bit/s of the container timeline (0: fixed quantiser)
  Rational containerFps{25, 1};
};

// DVD-Video limits (DVD Forum book 3): peak video rate 9.8 Mbit/s, VBV buffer 224 KiB (1835008 bits).
inline constexpr std::int64_t kDvdMaxVideoRate = 9'800'000;
inline constexpr int kDvdVbvBits = 1'835'008;

// The encoder's colour conversion: full-range RGB -> BT.601 limited-range YCbCr 4:2:0 (libswscale,
// bicubic chroma filter, bit-exact mode). Exposed so tests measure the codec against its real input.
Yuv420Image rgbaToYuv420(const Rgba8Image& img);

class Mpeg2Encoder {
 public:
  Mpeg2Encoder(int width, int height, const EncoderSettings& s);
  ~Mpeg2Encoder();
  Mpeg2Encoder(const Mpeg2Encoder&) = delete;
  Mpeg2Encoder& operator=(const Mpeg2Encoder&) = delete;

  // Encodes frame number `pts` (in 1/containerFps units). Owned packets are appended to `out`.
  void encode(const Rgba8Image& img, std::int64_t pts, std::vector<AVPacket*>& out);
  void flush(std::vector<AVPacket*>& out);

  const AVCodecContext* context() const { return ctx_; }
  // Largest quantiser_scale the encoder reported using (the VBV can force a coarser one).
  int maxQscaleUsed() const { return maxQ_; }

 private:
  void drain(std::vector<AVPacket*>& out);
  AVCodecContext* ctx_ = nullptr;
  SwsContext* sws_ = nullptr;
  AVFrame* frame_ = nullptr;
  int quality_ = 0;
  int maxQ_ = 0;
};

}  // namespace vbim::streams
