// The one exception type of the GS model: bad input (FIX out of range, a frame of the wrong size, a
// branch to a stream that does not exist, a VRAM layout that does not fit). what() says what was
// given and what was expected; the CLI turns it into a non-zero exit. keys() names the gs.* settings
// of the platform config that caused it, so a caller that read them from a file can point at the line.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "runtime/error.hpp"

namespace vbim::gs {

class GsError : public Error {
 public:
  using Error::Error;
  GsError(std::vector<std::string> keys, const std::string& message) : Error(message), keys_(std::move(keys)) {}

  // The platform config keys ("gs.strip_rows", ...) whose values led to the error; empty when no
  // setting is to blame (a frame of the wrong size, a branch to a missing stream).
  const std::vector<std::string>& keys() const { return keys_; }

 private:
  std::vector<std::string> keys_;
};

}  // namespace vbim::gs
