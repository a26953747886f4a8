// Every failure of the renderer (no GL context, a shader that does not compile, a run directory
// without frames, a camera outside the terrain) is a RenderError whose message names the input
// and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace vbim::render {

class RenderError : public std::runtime_error {
 public:
  explicit RenderError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace vbim::render
