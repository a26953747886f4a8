#include "streams/descriptor_probe.hpp"

#include <algorithm>
#include <array>

#include "streams/demuxer.hpp"

namespace vbim::streams {

namespace {

// The descriptor of the largest stream vbim writes fits in far fewer sectors (23 for a day at one
// frame per game minute); a stream whose first 4096 sectors hold no descriptor is not ours.
constexpr std::int64_t kMaxDescriptorSectors = 4096;

}  // namespace

ProbedDescriptor probeDescriptor(std::int64_t sectors, const ReadStreamSector& read, const std::string& where) {
  if (sectors == 0) throw StreamProbeError(where + ": not a VBIM stream: the file is empty");
  Demuxer demux;
  std::array<std::uint8_t, kSectorBytes> sector{};
  const std::int64_t limit = std::min(sectors, kMaxDescriptorSectors);
  for (std::int64_t s = 0; s < limit && !demux.descriptor(); ++s) {
    if (const std::string error = read(s, sector); !error.empty()) throw StreamProbeError(where + ": " + error);
    demux.feed(sector, static_cast<std::uint32_t>(s));
    for (const StreamError& e : demux.errors()) {
      if (e.kind == ErrorKind::BadPackHeader || e.kind == ErrorKind::BadDescriptor ||
          e.kind == ErrorKind::ShortSector) {
        throw StreamProbeError(where + ": not a VBIM stream: " + e.describe() +
                               " (expected MPEG-2 program stream packs of 2048 bytes with a vbim playback "
                               "descriptor)");
      }
    }
  }
  if (!demux.descriptor()) {
    throw StreamProbeError(where + ": not a VBIM stream: no playback descriptor in the first " + std::to_string(limit) +
                           " sectors (expected private_stream_2 descriptor packs at sector 0; `vbim author` writes "
                           "them, `vbim decode` reads MPEG video without them)");
  }
  ProbedDescriptor p;
  p.descriptor = *demux.descriptor();
  const Descriptor& d = p.descriptor;
  p.lightmapIndex = d.streamIndex(0xE0);
  p.skyIndex = d.streamIndex(0xE1);
  if (p.lightmapIndex < 0) throw StreamProbeError(where + ": the descriptor lists no lightmap stream (0xE0)");
  if (d.framesPerVariant == 0 || d.gameFps.num == 0 || d.gameFps.den == 0 || d.variants.empty()) {
    throw StreamProbeError(where + ": the descriptor has no frames, no variants or a zero frame rate");
  }
  if (static_cast<std::int64_t>(d.totalSectors) > sectors) {
    throw StreamProbeError(where + ": truncated: the descriptor says " + std::to_string(d.totalSectors) +
                           " sectors but the file has " + std::to_string(sectors));
  }
  return p;
}

}  // namespace vbim::streams
