// The one exception type of authoring: its message names the file (or frame) and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace vbim::streams {

class AuthoringError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vbim::streams
