// libavformat's MPEG-PS muxer ("vob": MPEG-2 pack headers, no DVD NAV placeholders) writing 2048-byte
// packs at the DVD mux rate into memory.
#pragma once

#include <cstdint>
#include <vector>

#include "streams/authoring/libav.hpp"

namespace vbim::streams {

// 10.08 Mbit/s = 25200 x 50 B/s, the DVD-Video program mux rate (docs/dependencies.md#program-mux-rate).
inline constexpr std::int64_t kDvdMuxRate = 10'080'000;

class PsMuxer {
 public:
  PsMuxer();
  ~PsMuxer();
  PsMuxer(const PsMuxer&) = delete;
  PsMuxer& operator=(const PsMuxer&) = delete;

  // Adds a video stream fed by `enc` (ids are given in creation order: 0xE0, 0xE1). Returns its index.
  int addStream(const AVCodecContext* enc);
  void begin();
  // Takes ownership of `pkt` (timestamps in the encoder's time base).
  void write(AVPacket* pkt, int stream, AVRational encoderTimeBase);
  // Writes the trailer and returns the whole program stream.
  std::vector<std::uint8_t> finish();

 private:
  AVFormatContext* oc_ = nullptr;
  bool begun_ = false;
};

}  // namespace vbim::streams
