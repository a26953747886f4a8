// Every failure of the renderer (no GL context, a shader that does not compile, a run directory
// without frames, a camera outside the terrain) is a RenderError whose message names the input
// and what was expected.
#pragma once

#include "runtime/error.hpp"

namespace vbim::render {

class RenderError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::render
