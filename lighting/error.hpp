// The one error type of the lighting generator: what() names the input (file or parameter), the
// place (pixel, key) and what was expected, so the CLI can print it as is.
#pragma once

#include "runtime/error.hpp"

namespace vbim::lighting {

class LightingError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::lighting
