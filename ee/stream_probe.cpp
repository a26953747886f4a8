#include "ee/stream_probe.hpp"

#include <string>

namespace vbim::ee {

ProbedStream probeStream(iop::SectorSource& disc, const iop::DiscFile& file) {
  const auto read = [&](std::int64_t s, std::span<std::uint8_t, streams::kSectorBytes> out) {
    const iop::SectorReadResult r = disc.read(file.lba + s, iop::SectorSpan(out));
    return r.ok ? std::string() : r.error;
  };
  const streams::ProbedDescriptor d =
      streams::probeDescriptor(file.sectors(), read, disc.describe() + ", file '" + file.path + "'");
  return ProbedStream{file, d.descriptor, d.lightmapIndex, d.skyIndex};
}

}  // namespace vbim::ee
