#include "streams/authoring/frame_author.hpp"

#include <sstream>

#include "streams/authoring/error.hpp"

namespace vbim::streams {

std::string authorFrameStream(const FrameAuthorRequest& r, const std::string& out,
                              const FrameAuthorProgressFn& progress) {
  const AuthorSettings settings = streamSettings(r.encode);
  const ToneMapping tone = toneMapping(r.encode);
  const InputEncoding enc = inputEncoding(r.input);
  FrameStream stream;
  if (!r.synthetic.empty()) {
    if (!r.sequences.frames.empty() || !r.sequences.variants.empty())
      throw AuthoringError("--synthetic replaces --frames and --variant; give one or the other");
    SyntheticDay day;
    day.frames = r.syntheticFrames;
    parseSize(r.syntheticSize, day.width, day.height, "--synthetic-size");
    parseSize(r.syntheticSkySize, day.skyWidth, day.skyHeight, "--synthetic-sky-size");
    stream = authorSyntheticStream(day, weatherList(r.synthetic), settings, tone, progress);
  } else {
    if (r.sequences.frames.empty()) {
      throw AuthoringError(
          "give a source: --frames PATTERN, --terrain FILE or --procedural (Technique A), or --synthetic");
    }
    stream = authorImageSequences(imageSequences(r.sequences, enc), settings, tone, progress);
  }
  writeStreamFile(out, stream.bytes);
  std::ostringstream lines;
  lines << out << ": " << stream.bytes.size() / 2048 << " sectors (" << stream.bytes.size() << " bytes)\n"
        << containerStretchNote(stream.containerStretch, settings.encoder.containerFps);
  return lines.str();
}

}  // namespace vbim::streams
