#include "sweep/outputs/reencoded_streams.hpp"

#include <filesystem>

#include "runtime/error.hpp"
#include "streams/authoring/transcode.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::sweep {

std::vector<std::shared_ptr<Stream>> reencodedStreams(const Stream& first, const std::string& path,
                                                      const std::vector<int>& qscales,
                                                      const std::vector<std::int64_t>& bitrates) {
  const std::string stem = std::filesystem::path(path).stem().string();
  const auto reencoded = [&](const streams::EncoderSettings& e) {
    return streams::transcodeStream(streams::readDiscFile(*first.disc, first.file), path, e);
  };
  std::vector<std::shared_ptr<Stream>> out;
  for (int q : qscales) {
    if (q < 1 || q > 31) throw Error("--qscale " + std::to_string(q) + ": expected 1..31");
    streams::EncoderSettings e;
    e.qscale = q;
    out.push_back(memoryStream(stem + "_q" + std::to_string(q), reencoded(e)));
  }
  for (std::int64_t b : bitrates) {
    if (b < 1 || b > streams::kDvdMaxVideoRate)
      throw Error("--bitrate " + std::to_string(b) + ": expected 1..9800000 bit/s");
    streams::EncoderSettings e;
    e.bitrate = b;
    out.push_back(memoryStream(stem + "_" + std::to_string(b / 1000) + "kbps", reencoded(e)));
  }
  return out;
}

std::vector<std::uint8_t> transcodePlanStream(const StreamSpec& s, std::vector<Yuv420Image>* sources) {
  streams::EncoderSettings e;
  if (s.bitrate > 0) e.bitrate = s.bitrate;
  if (s.qscale > 0) e.qscale = s.qscale;
  e.gop = s.gop;
  e.bFrames = s.bFrames;
  e.openGop = s.openGop;
  return streams::transcodeStream(s.path, e, sources);
}

}  // namespace vbim::sweep
