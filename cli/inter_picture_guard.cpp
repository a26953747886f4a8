#include "cli/inter_picture_guard.hpp"

#include <optional>

#include "cli/command.hpp"
#include "ee/stream_probe.hpp"

namespace vbim::cli {

void refuseInterPictures(iop::SectorSource& disc, const iop::DiscFile& file, const std::string& shown) {
  std::optional<streams::Descriptor> d;
  try {
    d = ee::probeStream(disc, file).descriptor;
  } catch (const std::exception&) {
    return;  // not a VBIM stream, or damaged: reported by the command as before
  }
  if (d->intraOnly()) return;
  throw Exit(2, shown +
                    ": P and B pictures are not played yet (issue #29): this stream has GOPs (descriptor version 2); "
                    "`vbim decode` decodes it, `vbim info` shows its GOPs");
}

}  // namespace vbim::cli
