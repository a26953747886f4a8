#include "cli/profile_transcode.hpp"

#include <fstream>
#include <iterator>
#include <map>

#include "cli/command.hpp"
#include "streams/authoring/authoring_error.hpp"
#include "streams/authoring/mpeg2_decoder.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/demuxer.hpp"
#include "streams/format.hpp"

namespace vbim::cli::profile {
namespace {

// The container frame rate to re-encode at: the MPEG-2 frame rate whose period is the longest one
// dividing the stream's PTS step (the writer may have stretched the step to a multiple of it, see
// StreamWriter::containerStretch); 25 fps if none does.
streams::Rational containerRate(std::uint32_t ptsPerFrame) {
  constexpr streams::Rational kRates[] = {{24, 1}, {25, 1}, {30000, 1001}, {30, 1}, {50, 1}, {60, 1}};
  for (const streams::Rational r : kRates) {
    const std::uint64_t period = std::uint64_t{90'000} * r.den / r.num;
    if (std::uint64_t{90'000} * r.den % r.num == 0 && ptsPerFrame % period == 0) return r;
  }
  return {25, 1};
}

}  // namespace

std::vector<std::uint8_t> transcodeStream(const std::filesystem::path& path, streams::EncoderSettings encoder) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Exit(2, path.string() + ": cannot open the stream to re-encode");
  streams::Demuxer dmx;
  std::vector<std::uint8_t> sector(2048);
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> pictures;  // (stream, global frame)
  for (std::uint32_t lsn = 0; in.read(reinterpret_cast<char*>(sector.data()), 2048); ++lsn) {
    dmx.feed(sector, lsn);
    for (streams::Picture& p : dmx.pictures()) {
      if (p.frame && !p.damaged) pictures[{p.streamId == 0xE0 ? 0 : 1, *p.frame}] = std::move(p.data);
    }
    dmx.pictures().clear();
  }
  dmx.finish();
  for (streams::Picture& p : dmx.pictures()) {
    if (p.frame && !p.damaged) pictures[{p.streamId == 0xE0 ? 0 : 1, *p.frame}] = std::move(p.data);
  }
  if (!dmx.descriptor())
    throw Exit(2, path.string() + ": not a VBIM stream (no playback descriptor); cannot re-encode");
  const streams::Descriptor& d = *dmx.descriptor();
  const bool sky = d.streamIndex(0xE1) >= 0;

  streams::AuthorSettings s;
  s.gameFps = d.gameFps;
  s.loopFrame = d.loopFrame;
  s.withSky = sky;
  s.encoder = encoder;
  s.encoder.containerFps = containerRate(d.ptsPerFrame);
  try {
    streams::StreamWriter w(s);
    streams::Mpeg2Decoder dec;
    for (std::size_t v = 0; v < d.variants.size(); ++v) {
      w.beginVariant(d.variants[v].name);
      for (std::uint32_t f = 0; f < d.framesPerVariant; ++f) {
        const std::uint32_t g = static_cast<std::uint32_t>(v) * d.framesPerVariant + f;
        auto lm = pictures.find({0, g});
        if (lm == pictures.end())
          throw Exit(2, path.string() + ": lightmap picture of frame " + std::to_string(g) + " is missing or damaged");
        const Rgba8Image lmImg = dec.decodeRgba(lm->second);
        if (!sky) {
          w.addFrame(lmImg);
          continue;
        }
        auto sk = pictures.find({1, g});
        if (sk == pictures.end())
          throw Exit(2, path.string() + ": sky picture of frame " + std::to_string(g) + " is missing or damaged");
        const Rgba8Image skyImg = dec.decodeRgba(sk->second);
        w.addFrame(lmImg, &skyImg);
      }
    }
    return w.finish();
  } catch (const streams::AuthoringError& e) {
    throw Exit(2, path.string() + ": re-encoding failed: " + e.what());
  }
}

}  // namespace vbim::cli::profile
