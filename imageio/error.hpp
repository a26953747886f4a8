// The one error type of imageio: what() names the file and what was expected or what failed, so a
// command can print it as it is.
#pragma once

#include <stdexcept>

namespace vbim::imageio {

class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vbim::imageio
