// The one error type of imageio: what() names the file and what was expected or what failed, so a
// command can print it as it is.
#pragma once

#include "runtime/error.hpp"

namespace vbim::imageio {

class ImageIoError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::imageio
