// Shared by the two sources of `vbim author` (image sequences / synthetic day in cmd_author.cpp,
// Technique A in author_terrain.cpp): the encoder and tone-mapping options.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::cli {

// What every `vbim author` source encodes with.
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

// Registers --fps, --container-fps, --loop, --q, --bitrate, --gop, --b-frames, --open-gop, --exposure,
// --tone, --transfer, --white.
void addEncodeOptions(CLI::App* cmd, EncodeOptions& o);
// Throw Exit(2, ...) naming the option on a bad value.
streams::AuthorSettings streamSettings(const EncodeOptions& o);
streams::ToneMapping toneMapping(const EncodeOptions& o);

// "N" or "N/D", both positive; Exit(2) naming `what` otherwise.
streams::Rational parseRational(const std::string& s, const char* what);
// "WxH"; Exit(2) naming `what` otherwise.
void parseSize(const std::string& s, int& w, int& h, const char* what);

}  // namespace vbim::cli
