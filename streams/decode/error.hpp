// The error of vbim decode's library (streams/decode/): a stream that cannot be decoded at all; the message names the
// file and, where known, the byte.
#pragma once

#include "runtime/error.hpp"

namespace vbim::streams {

class DecodeError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::streams
