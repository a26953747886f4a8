// Image sequences or the synthetic day generator -> one VBIM stream with its authoring record: what
// `vbim author --frames ...` and `vbim author --synthetic ...` make (Technique A, which renders its
// own frames, is lighting/authoring/technique_a_stream.hpp).
//
//   vbim::streams::ImageSequences in;
//   in.variants = {{"clear", "lm/lightmap_%04d.exr", "lm/sky_%04d.exr"}};
//   const auto s = vbim::streams::authorImageSequences(in, settings, tone);
//   vbim::streams::writeStreamFile("day.vbim", s.bytes);
//
// The frames are read by imageio (any format OpenImageIO reads), brought to 8 bits by the tone
// mapping (tone_map.hpp) and encoded and muxed by the StreamWriter. Every problem (a pattern that
// matches no file, a variant without the sky the first one has, frame counts or sizes that differ,
// a file that cannot be read) is thrown as AuthoringError naming the input. Host time only: the
// stream's cost on the simulated clock is the player's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {

// One variant (weather) of an image-sequence stream: its name and its frames' patterns
// (frame_pattern.hpp). Every variant has a sky sequence, or none has.
struct SequenceVariant {
  std::string name;
  std::string lightmaps;
  std::string skies;  // "" for none
};

struct ImageSequences {
  std::vector<SequenceVariant> variants;  // in stream order; at least one
  InputEncoding input = InputEncoding::Auto;
};

struct FrameAuthorProgress {
  std::size_t done = 0;   // frames encoded so far, all variants
  std::size_t total = 0;  // frames in the stream
  std::string label;      // the frame just encoded: its file name, or "WEATHER N"
};
using FrameAuthorProgressFn = std::function<void(const FrameAuthorProgress&)>;

struct FrameStream {
  std::vector<std::uint8_t> bytes;     // the whole stream, 2048-byte packs, its authoring record appended
  std::uint32_t containerStretch = 1;  // StreamWriter::containerStretch()
};

// The synthetic day (synthetic_day.hpp), one variant per weather in `weathers`; `day.weather` is
// ignored, and `settings.withSky` follows `day.skyWidth` (0: no sky).
FrameStream authorSyntheticStream(SyntheticDay day, const std::vector<std::string>& weathers, AuthorSettings settings,
                                  const ToneMapping& tone, const FrameAuthorProgressFn& progress = {});

// Image files; `settings.withSky` follows the first variant.
FrameStream authorImageSequences(const ImageSequences& in, AuthorSettings settings, const ToneMapping& tone,
                                 const FrameAuthorProgressFn& progress = {});

// The line `vbim author` prints when the writer spaced the frames more than one container period
// apart (StreamWriter::containerStretch): "" when `stretch` is 1.
std::string containerStretchNote(std::uint32_t stretch, Rational containerFps);

}  // namespace vbim::streams
