// One MPEG-2 video encoder (libavcodec): RGBA8 frames in, one coded picture per frame out. Intra-only
// by default; with a GOP longer than 1 it writes P pictures, and B pictures with bFrames > 0 (coded
// after the picture they are shown before: packets come out in stream order, pts in display order).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/image.hpp"
#include "streams/authoring/libav.hpp"
#include "streams/descriptor.hpp"

namespace vbim::streams {

struct EncoderSettings {
  int qscale = 3;            // fixed quantiser_scale 1..31 (used when bitrate == 0)
  std::int64_t bitrate = 0;  // target bit/s of the container timeline (0: fixed quantiser)
  Rational containerFps{25, 1};
  // GOP structure (13818-2 §6.3.8): gop pictures from one I picture to the next (1: every picture I),
  // up to bFrames B pictures between references, closed GOPs (no B picture refers across a GOP
  // header) unless openGop.
  int gop = 1;
  int bFrames = 0;
  bool openGop = false;
};

// Longest GOP `vbim author --gop` takes: temporal_reference, a picture's display position in its
// GOP, is 10 bits (13818-2 §6.3.9).
inline constexpr int kMaxGop = 1024;
// Most B pictures in a row libavcodec's MPEG-2 encoder takes (MAX_B_FRAMES in mpegvideo.h).
inline constexpr int kMaxBFrames = 16;
// Checks gop and bFrames; returns what is wrong (naming the options of `vbim author`), or empty.
std::string gopProblem(const EncoderSettings& s);

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
  // `force` makes the picture an I picture (a GOP starts there) or the last reference before one;
  // NONE lets the GOP structure decide.
  enum class Force { None, Intra, Reference };
  void encode(const Rgba8Image& img, std::int64_t pts, std::vector<AVPacket*>& out, Force force = Force::None);
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
  bool intraOnly_ = true;
};

}  // namespace vbim::streams
