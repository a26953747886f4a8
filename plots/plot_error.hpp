// The one error type of plots/: a figure could not be drawn or written. The message names the file.
#pragma once

#include <stdexcept>

namespace vbim::plots {

class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vbim::plots
