#include "sweep/outputs/stream_quality.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/error.hpp"
#include "streams/decode/stream_decode.hpp"
#include "streams/format.hpp"

namespace vbim::sweep {

double lumaPsnr(std::span<const std::uint8_t> a, std::size_t aStride, std::span<const std::uint8_t> b,
                std::size_t bStride, int width, int height) {
  std::uint64_t sse = 0;
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* ra = a.data() + static_cast<std::size_t>(y) * aStride;
    const std::uint8_t* rb = b.data() + static_cast<std::size_t>(y) * bStride;
    for (int x = 0; x < width; ++x) {
      const int d = int{ra[x]} - int{rb[x]};
      sse += static_cast<std::uint64_t>(d * d);
    }
  }
  if (sse == 0) return kIdenticalPsnrDb;
  const double samples = static_cast<double>(width) * static_cast<double>(height);
  return std::min(kIdenticalPsnrDb, 10.0 * std::log10(255.0 * 255.0 * samples / static_cast<double>(sse)));
}

StreamQuality measureStreamQuality(std::span<const std::uint8_t> reencoded, const std::string& name,
                                   const std::vector<Yuv420Image>& sources) {
  streams::DecodeOptions options;
  options.streamId = streams::kLightmapStream;
  StreamQuality q;
  double sum = 0;
  q.minDb = kIdenticalPsnrDb;
  const auto frame = [&](int n, const ipu::Decoder& decoder) {
    const auto i = static_cast<std::size_t>(n);
    if (i >= sources.size()) {
      throw Error(name + ": the re-encode decodes to more lightmap frames than the " + std::to_string(sources.size()) +
                  " it was made from");
    }
    const Yuv420Image& src = sources[i];
    const ipu::FrameStore* f = decoder.displayFrame();
    if (f == nullptr || decoder.displayWidth() != src.width || decoder.displayHeight() != src.height) {
      throw Error(name + ": lightmap frame " + std::to_string(n) + " of the re-encode is not " +
                  std::to_string(src.width) + "x" + std::to_string(src.height) + " like its source");
    }
    const double db = lumaPsnr(f->y, static_cast<std::size_t>(f->lumaStride), src.y,
                               static_cast<std::size_t>(src.width), src.width, src.height);
    sum += db;
    q.minDb = std::min(q.minDb, db);
    ++q.frames;
  };
  // A re-encode that does not decode throws vbim::Error naming `name` and the place.
  streams::decodeStream(reencoded, name, options, frame, [](const std::string&) {});
  if (q.frames != static_cast<std::int64_t>(sources.size())) {
    throw Error(name + ": the re-encode decodes to " + std::to_string(q.frames) + " lightmap frames, not the " +
                std::to_string(sources.size()) + " it was made from");
  }
  q.meanDb = q.frames > 0 ? sum / static_cast<double>(q.frames) : 0.0;
  return q;
}

}  // namespace vbim::sweep
