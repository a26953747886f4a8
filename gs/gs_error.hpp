// The one exception type of the GS model: bad input (FIX out of range, a frame of the wrong size, a
// branch to a stream that does not exist, a VRAM layout that does not fit). what() says what was
// given and what was expected; the CLI turns it into a non-zero exit.
#pragma once

#include <stdexcept>

namespace vbim::gs {

class GsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vbim::gs
