// `vbim author --frames/--sky/--variant/--variant-sky/--input`, as text, read into the image
// sequences authorImageSequences takes (frame_stream.hpp). Each throws AuthoringError naming the
// option on a bad value.
#pragma once

#include <string>
#include <vector>

#include "streams/authoring/frame_stream.hpp"

namespace vbim::streams {

struct SequenceOptions {
  std::string name = "default";           // --name: the variant of frames/sky
  std::string frames, sky;                // --frames, --sky
  std::vector<std::string> variants;      // --variant NAME=LIGHTMAP_PATTERN, in order
  std::vector<std::string> variantSkies;  // --variant-sky NAME=SKY_PATTERN
};

// --input: auto, linear or encoded.
InputEncoding inputEncoding(const std::string& text);

// The first variant from frames/sky, then each --variant with its --variant-sky, in stream order; a
// --variant-sky naming no --variant is refused.
ImageSequences imageSequences(const SequenceOptions& o, InputEncoding input);

// "clear,overcast": the --synthetic weathers in order.
std::vector<std::string> weatherList(const std::string& text);

}  // namespace vbim::streams
