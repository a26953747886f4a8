#include "streams/video_elementary_stream.hpp"

#include <algorithm>

#include "streams/format.hpp"
#include "streams/program_stream.hpp"

namespace vbim::streams {

StreamForm detectStreamForm(std::span<const std::uint8_t> file) {
  static constexpr std::uint8_t kPrefix[3] = {0, 0, 1};
  if (file.size() >= 4 && file[0] == 0 && file[1] == 0 && file[2] == 1 && file[3] == kPackStartCode)
    return StreamForm::ProgramStream;
  if (std::search(file.begin(), file.end(), std::begin(kPrefix), std::end(kPrefix)) != file.end())
    return StreamForm::ElementaryStream;
  return StreamForm::NotMpeg;
}

std::uint64_t VideoElementaryStream::fileOffsetOf(std::size_t esOffset) const {
  if (runs.empty()) return esOffset;
  auto it = std::upper_bound(runs.begin(), runs.end(), esOffset,
                             [](std::size_t off, const Run& r) { return off < r.esOffset; });
  if (it != runs.begin()) --it;
  return it->fileOffset + (esOffset - it->esOffset);
}

VideoElementaryStream readVideoStream(std::span<const std::uint8_t> programStream,
                                      std::optional<std::uint8_t> streamId) {
  VideoElementaryStream out;
  ProgramStreamReader reader(programStream);
  ParsedPack pack;
  while (reader.next(pack)) {
    for (const PesPacket& p : pack.packets) {
      if (!isVideoStream(p.streamId)) continue;
      if (!out.streamId && (!streamId || *streamId == p.streamId)) out.streamId = p.streamId;
      if (p.streamId != out.streamId || p.payload.empty()) continue;
      out.runs.push_back({out.bytes.size(), p.payloadOffset});
      out.bytes.insert(out.bytes.end(), p.payload.begin(), p.payload.end());
    }
  }
  out.defects = reader.defects();
  return out;
}

VideoElementaryStream rawVideoStream(std::span<const std::uint8_t> file) {
  VideoElementaryStream out;
  out.bytes.assign(file.begin(), file.end());
  out.runs.push_back({0, 0});
  return out;
}

}  // namespace vbim::streams
