// What `vbim decode` reads and how its options name things: the input's bytes (a file as it is, or
// the stream on an ISO 9660 image), a PES stream id as typed, a frame file format by name. Not
// model code; no simulated time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "streams/decode/frame_files.hpp"

namespace vbim::streams {

struct DecodeInput {
  std::vector<std::uint8_t> bytes;
  std::string name;        // how messages name it: the path, and on an image the file on it
  std::string fileOnDisc;  // the file on an ISO 9660 image ("\\DATA\\DAY.VBI;1"), or empty
};

// `input` as it is, or, when it is an ISO 9660 image or `file` is given (--file), the stream `file`
// on it (its only VBIM stream when `file` is empty). Throws vbim::Error naming the path.
DecodeInput readDecodeInput(const std::string& input, const std::string& file);

// "0xE1", "225": a PES stream id; vbim::Error naming --stream-id otherwise.
std::uint8_t parseStreamId(const std::string& text);

// "png", "exr", "yuv" or "rgba" (anything else: png; the command checks the name).
FrameFileFormat frameFileFormatNamed(const std::string& name);

}  // namespace vbim::streams
