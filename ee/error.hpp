// The EE's error: the stream file on the disc is not a VBIM stream the player can play (no
// descriptor, a malformed one, a stream without a lightmap). Thrown by probeStream before a run.
#pragma once

#include "runtime/error.hpp"

namespace vbim::ee {

class StreamProbeError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::ee
