// Before a run: the playback descriptor of a stream, read from its first sectors, so that the player
// knows the streams' sizes, rates, loop point, variants and index. This is the "is this a VBIM
// stream?" check: anything else is refused with the place and the reason. The sectors come through
// a callback, so the reader needs no disc: the EE's probe (ee/stream_probe.hpp) reads them from
// the IOP's disc, the disc-image tools (streams/disc/) from an ISO 9660 image.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "runtime/error.hpp"
#include "streams/descriptor.hpp"
#include "streams/format.hpp"

namespace vbim::streams {

// The stream is not one the player can play (no descriptor, a malformed one, no lightmap stream,
// fewer sectors than the descriptor says). The disc-image tools tell it from other errors: a file
// on an image that throws it is not a VBIM stream.
class StreamProbeError : public Error {
 public:
  using Error::Error;
};

// Reads sector `sector` of the stream file into `out`: returns empty when it was read, else why not.
using ReadStreamSector = std::function<std::string(std::int64_t sector, std::span<std::uint8_t, kSectorBytes> out)>;

struct ProbedDescriptor {
  Descriptor descriptor;
  int lightmapIndex = -1;  // position of the 0xE0 stream in descriptor.streams
  int skyIndex = -1;       // position of the 0xE1 stream, or -1 when the stream has no sky
};

// Reads the first of the file's `sectors` until the descriptor is complete. Throws StreamProbeError
// starting with `where` (the disc and the file), naming the sector and byte offset and what was
// expected.
ProbedDescriptor probeDescriptor(std::int64_t sectors, const ReadStreamSector& read, const std::string& where);

}  // namespace vbim::streams
