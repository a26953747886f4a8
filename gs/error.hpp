// The one exception type of the GS model: bad input (FIX out of range, a frame of the wrong size, a
// branch to a stream that does not exist, a VRAM layout that does not fit). what() says what was
// given and what was expected; the CLI turns it into a non-zero exit.
#pragma once

#include "runtime/error.hpp"

namespace vbim::gs {

class GsError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::gs
