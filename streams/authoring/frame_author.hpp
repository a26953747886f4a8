// `vbim author --frames ... | --synthetic ...` as a library call: the command's values (the image
// sequences or the synthetic day's weathers and sizes, --input, the encoder's options) authored into
// one VBIM stream file, and the lines said about it. Technique A (--terrain, --procedural) is
// lighting/authoring/terrain_author.hpp. Host time only: the stream's cost is the player's.
#pragma once

#include <cstdint>
#include <string>

#include "streams/authoring/encode_options.hpp"
#include "streams/authoring/frame_stream.hpp"
#include "streams/authoring/sequence_options.hpp"

namespace vbim::streams {

struct FrameAuthorRequest {
  SequenceOptions sequences;  // --frames, --sky, --name, --variant, --variant-sky
  EncodeOptions encode;
  std::string input = "auto";  // inputEncoding's
  std::string synthetic;       // --synthetic WEATHER[,WEATHER]: the synthetic day instead of files
  std::uint32_t syntheticFrames = 48;
  std::string syntheticSize = "256x256", syntheticSkySize = "128x64";  // WxH; a sky of 0x0: none
};

// Authors the stream and writes it to `out` (complete or left as it was, writeStreamFile); returns
// what `vbim author` prints about it (its sectors and bytes, and containerStretchNote's line). Throws
// AuthoringError for a bad value (named by its option), no source, or both sources given.
std::string authorFrameStream(const FrameAuthorRequest& r, const std::string& out,
                              const FrameAuthorProgressFn& progress = {});

}  // namespace vbim::streams
