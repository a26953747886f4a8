// `vbim play`, `profile` and `replay` on a stream with P or B pictures (descriptor version 2): the
// player's P/B path on the simulated clock is not there yet (issue #29, item 4), so such a stream is
// refused with a message instead of played as garbage. `vbim decode` takes it.
#pragma once

#include <string>

#include "iop/sector_source.hpp"

namespace vbim::cli {

// Throws Exit(2) naming `shown` when the stream's descriptor lists a P or B picture. A stream without
// a readable descriptor passes: the command's own checks report it.
void refuseInterPictures(iop::SectorSource& disc, const iop::DiscFile& file, const std::string& shown);

}  // namespace vbim::cli
