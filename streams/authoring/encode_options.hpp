// What every `vbim author` source encodes with, as the command line gives it (text: "30000/1001",
// "gamma:2.2"), and its reading into the writer's settings. Shared by the image sequences, the
// synthetic day (streams/authoring/frame_stream.hpp) and Technique A
// (lighting/authoring/terrain_author.hpp). Not model code; no simulated time.
#pragma once

#include <cstdint>
#include <string>

#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {

struct EncodeOptions {
  std::string fps = "1", containerFps = "25";
  std::uint32_t loop = 0;
  int q = 3;
  std::int64_t bitrate = 0;
  double exposure = 0;
  std::string tone = "clamp", transfer = "srgb";
  double white = 255;
  int gop = 1, bFrames = 0;
  bool openGop = false;
};

// Each throws AuthoringError naming the option (--fps, --white, ...) on a bad value.
AuthorSettings streamSettings(const EncodeOptions& o);
ToneMapping toneMapping(const EncodeOptions& o);

// "N" or "N/D", both positive; AuthoringError naming `what` otherwise.
Rational parseRational(const std::string& s, const char* what);
// "WxH"; AuthoringError naming `what` otherwise.
void parseSize(const std::string& s, int& w, int& h, const char* what);

}  // namespace vbim::streams
