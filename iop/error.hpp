// The IOP's error: a problem with a disc image (missing, unreadable, truncated, no such file). what() names the
// image, the place (byte offset, LBA or path) and what was expected.
#pragma once

#include "runtime/error.hpp"

namespace vbim::iop {

class DiscError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::iop
