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
  s.encoder.containerFps = streams::Rational{90'000, d.ptsPerFrame};
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
