// Before a run: read the playback descriptor of the stream file on the disc, on the host, so the
// player knows the streams' sizes, rates, loop point, variants and index. This is the
// "is this a VBIM stream?" check (streams/descriptor_probe.hpp) on the IOP's disc: anything else is
// rejected with the place and the reason.
#pragma once

#include "iop/sector_source.hpp"
#include "streams/descriptor.hpp"
#include "streams/descriptor_probe.hpp"

namespace vbim::ee {

struct ProbedStream {
  iop::DiscFile file;
  streams::Descriptor descriptor;
  int lightmapIndex = -1;  // position of the 0xE0 stream in descriptor.streams
  int skyIndex = -1;       // position of the 0xE1 stream, or -1 when the stream has no sky
};

// Reads the first sectors of `file` until the descriptor is complete. Throws streams::StreamProbeError naming
// the disc, the file, the sector and byte offset, and what was expected.
ProbedStream probeStream(iop::SectorSource& disc, const iop::DiscFile& file);

}  // namespace vbim::ee
