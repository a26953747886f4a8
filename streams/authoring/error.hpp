// The one exception type of authoring: its message names the file (or frame) and the problem.
#pragma once

#include "runtime/error.hpp"

namespace vbim::streams {

class AuthoringError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::streams
