#include "streams/authoring/bench_stream.hpp"

#include "runtime/rng.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {

namespace {

Rgba8Image noiseImage(int w, int h, Rng& rng) {
  Rgba8Image img(w, h);
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = (i % 4 == 3) ? 0x80 : static_cast<std::uint8_t>(rng.below(256));
  return img;
}

}  // namespace

std::vector<std::uint8_t> authorBenchStream(int frames, BenchContent content, int qscale, bool stretchContainerTime) {
  streams::AuthorSettings s;
  s.stretchContainerTime = stretchContainerTime;
  s.gameFps = streams::Rational{1, 2};  // 2 s of game time per stream frame
  s.encoder.qscale = qscale;
  streams::StreamWriter w(s);
  w.beginVariant("bench");
  streams::SyntheticDay day;
  day.width = day.height = 512;
  day.skyWidth = 256;
  day.skyHeight = 128;
  day.frames = static_cast<std::uint32_t>(frames);
  Rng rng(7);
  const streams::ToneMapping tone;
  for (int f = 0; f < frames; ++f) {
    if (content == BenchContent::Noise) {
      const Rgba8Image lm = noiseImage(512, 512, rng), sky = noiseImage(256, 128, rng);
      w.addFrame(lm, &sky);
    } else {
      const Rgba8Image lm = streams::toneMap(streams::syntheticLightmap(day, static_cast<std::uint32_t>(f)), tone);
      const Rgba8Image sky = streams::toneMap(streams::syntheticSky(day, static_cast<std::uint32_t>(f)), tone);
      w.addFrame(lm, &sky);
    }
  }
  return w.finish();
}

}  // namespace vbim::streams
