// The one error type of the lighting generator: what() names the input (file or parameter), the
// place (pixel, key) and what was expected, so the CLI can print it as is.
#pragma once

#include <stdexcept>

namespace vbim::lighting {

class LightingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vbim::lighting
