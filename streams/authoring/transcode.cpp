#include "streams/authoring/transcode.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "streams/authoring/error.hpp"
#include "streams/authoring/mpeg2_decoder.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/demuxer.hpp"
#include "streams/format.hpp"

namespace vbim::streams {
namespace {

// The container frame rate to re-encode at: the MPEG-2 frame rate whose period is the longest one
// dividing the stream's PTS step (the writer may have stretched the step to a multiple of it, see
// StreamWriter::containerStretch); 25 fps if none does.
Rational containerRate(std::uint32_t ptsPerFrame) {
  constexpr Rational kRates[] = {{24, 1}, {25, 1}, {30000, 1001}, {30, 1}, {50, 1}, {60, 1}};
  for (const Rational r : kRates) {
    const std::uint64_t period = std::uint64_t{90'000} * r.den / r.num;
    if (std::uint64_t{90'000} * r.den % r.num == 0 && ptsPerFrame % period == 0) return r;
  }
  return {25, 1};
}

}  // namespace

std::vector<std::uint8_t> transcodeStream(const std::filesystem::path& path, EncoderSettings encoder,
                                          std::vector<Yuv420Image>* sources) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw AuthoringError(path.string() + ": cannot open the stream to re-encode");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return transcodeStream(bytes, path.string(), encoder, sources);
}

std::vector<std::uint8_t> transcodeStream(std::span<const std::uint8_t> stream, const std::string& name,
                                          EncoderSettings encoder, std::vector<Yuv420Image>* sources) {
  Demuxer dmx;
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> pictures;  // (stream, global frame)
  const auto keep = [&] {
    for (Picture& p : dmx.pictures()) {
      if (p.frame && !p.damaged) pictures[{p.streamId == kLightmapStream ? 0 : 1, *p.frame}] = std::move(p.data);
    }
    dmx.pictures().clear();
  };
  // Whole sectors only, as the drive reads them.
  for (std::uint32_t lsn = 0; (lsn + 1) * std::size_t{kSectorBytes} <= stream.size(); ++lsn) {
    dmx.feed(stream.subspan(lsn * std::size_t{kSectorBytes}, kSectorBytes), lsn);
    keep();
  }
  dmx.finish();
  keep();
  if (!dmx.descriptor()) throw AuthoringError(name + ": not a VBIM stream (no playback descriptor); cannot re-encode");
  const Descriptor& d = *dmx.descriptor();
  const bool sky = d.streamIndex(kSkyStream) >= 0;

  // Every picture first: a missing one is the input's fault, not the encoder's.
  const std::uint32_t frames = static_cast<std::uint32_t>(d.variants.size()) * d.framesPerVariant;
  for (std::uint32_t g = 0; g < frames; ++g) {
    if (!pictures.contains({0, g}))
      throw AuthoringError(name + ": lightmap picture of frame " + std::to_string(g) + " is missing or damaged");
    if (sky && !pictures.contains({1, g}))
      throw AuthoringError(name + ": sky picture of frame " + std::to_string(g) + " is missing or damaged");
  }

  AuthorSettings s;
  s.gameFps = d.gameFps;
  s.loopFrame = d.loopFrame;
  s.withSky = sky;
  s.encoder = encoder;
  s.encoder.containerFps = containerRate(d.ptsPerFrame);
  try {
    StreamWriter w(s);
    Mpeg2Decoder dec;
    for (std::size_t v = 0; v < d.variants.size(); ++v) {
      w.beginVariant(d.variants[v].name);
      for (std::uint32_t f = 0; f < d.framesPerVariant; ++f) {
        const std::uint32_t g = static_cast<std::uint32_t>(v) * d.framesPerVariant + f;
        const Rgba8Image lightmap = dec.decodeRgba(pictures.at({0, g}));
        if (sources != nullptr) sources->push_back(rgbaToYuv420(lightmap));
        if (!sky) {
          w.addFrame(lightmap);
          continue;
        }
        const Rgba8Image skyImage = dec.decodeRgba(pictures.at({1, g}));
        w.addFrame(lightmap, &skyImage);
      }
    }
    return w.finish();
  } catch (const AuthoringError& e) {
    throw AuthoringError(name + ": re-encoding failed: " + e.what());
  }
}

}  // namespace vbim::streams
