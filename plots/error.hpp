// The one error type of plots/: a figure could not be drawn or written. The message names the file.
#pragma once

#include "runtime/error.hpp"

namespace vbim::plots {

class PlotError : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::plots
