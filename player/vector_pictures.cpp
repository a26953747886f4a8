#include "player/vector_pictures.hpp"

#include "iop/sector_source.hpp"
#include "runtime/error.hpp"
#include "streams/demuxer.hpp"

namespace vbim::player {

StreamPictures picturesOf(const VectorStream& s) {
  streams::Demuxer demux;
  const std::size_t sectors = s.bytes.size() / iop::kSectorBytes;
  for (std::size_t i = 0; i < sectors; ++i) {
    demux.feed(s.bytes.subspan(i * iop::kSectorBytes, iop::kSectorBytes), static_cast<std::uint32_t>(i));
  }
  demux.finish();
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint8_t>> out;
  for (streams::Picture& p : demux.pictures()) {
    if (p.frame && !p.damaged) out[{p.streamId, *p.frame}] = std::move(p.data);
  }
  if (!demux.descriptor() || out.empty()) {
    throw ConfigError("stream '" + s.label + "': no playback descriptor or no picture to make IPU vectors from");
  }
  return StreamPictures{*demux.descriptor(), std::move(out)};
}

}  // namespace vbim::player
