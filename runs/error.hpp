// The one error of runs/ a caller tells apart: a failure while the run goes (a picture, stats.json
// or a digest that cannot be written or made), where every other vbim::Error is bad input. The
// command line ends the first with exit 1 and the others with exit 2 (docs/cli.md).
#pragma once

#include "runtime/error.hpp"

namespace vbim::runs {

class RunFailure : public Error {
 public:
  using Error::Error;
};

}  // namespace vbim::runs
