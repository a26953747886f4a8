#include "ee/stream_probe.hpp"

#include <array>
#include <string>

#include "streams/demuxer.hpp"

namespace vbim::ee {

namespace {

// The descriptor of the largest stream vbim writes fits in far fewer sectors (23 for a day at one
// frame per game minute); a stream whose first 4096 sectors hold no descriptor is not ours.
constexpr std::int64_t kMaxDescriptorSectors = 4096;

}  // namespace

ProbedStream probeStream(iop::SectorSource& disc, const iop::DiscFile& file) {
  const std::string where = disc.describe() + ", file '" + file.path + "'";
  if (file.sectors() == 0) throw StreamProbeError(where + ": not a VBIM stream: the file is empty");
  streams::Demuxer demux;
  std::array<std::uint8_t, iop::kSectorBytes> sector{};
  const std::int64_t limit = std::min(file.sectors(), kMaxDescriptorSectors);
  for (std::int64_t s = 0; s < limit && !demux.descriptor(); ++s) {
    const iop::SectorReadResult r = disc.read(file.lba + s, iop::SectorSpan(sector));
    if (!r.ok) throw StreamProbeError(where + ": " + r.error);
    demux.feed(sector, static_cast<std::uint32_t>(s));
    for (const streams::StreamError& e : demux.errors()) {
      if (e.kind == streams::ErrorKind::BadPackHeader || e.kind == streams::ErrorKind::BadDescriptor ||
          e.kind == streams::ErrorKind::ShortSector) {
        throw StreamProbeError(where + ": not a VBIM stream: " + e.describe() +
                               " (expected MPEG-2 program stream packs of 2048 bytes with a vbim playback "
                               "descriptor)");
      }
    }
  }
  if (!demux.descriptor()) {
    throw StreamProbeError(where + ": not a VBIM stream: no playback descriptor in the first " + std::to_string(limit) +
                           " sectors (expected private_stream_2 descriptor packs at sector 0)");
  }
  ProbedStream p;
  p.file = file;
  p.descriptor = *demux.descriptor();
  const streams::Descriptor& d = p.descriptor;
  p.lightmapIndex = d.streamIndex(0xE0);
  p.skyIndex = d.streamIndex(0xE1);
  if (p.lightmapIndex < 0) throw StreamProbeError(where + ": the descriptor lists no lightmap stream (0xE0)");
  if (d.framesPerVariant == 0 || d.gameFps.num == 0 || d.gameFps.den == 0 || d.variants.empty()) {
    throw StreamProbeError(where + ": the descriptor has no frames, no variants or a zero frame rate");
  }
  if (static_cast<std::int64_t>(d.totalSectors) > file.sectors()) {
    throw StreamProbeError(where + ": truncated: the descriptor says " + std::to_string(d.totalSectors) +
                           " sectors but the file has " + std::to_string(file.sectors()));
  }
  return p;
}

}  // namespace vbim::ee
