#include "runs/console_check.hpp"

#include "config/option_values.hpp"
#include "ee/stream_probe.hpp"
#include "gs/draw_checks.hpp"
#include "gs/error.hpp"

namespace vbim::runs {

PresentedSizes presentedSizes(const streams::StreamDisc* disc) {
  if (disc == nullptr) return {};
  const ee::ProbedStream probed = ee::probeStream(*disc->disc, disc->file);
  const auto size = [&](int index) {
    const streams::StreamEntry& e = probed.descriptor.streams[static_cast<std::size_t>(index)];
    return gs::PictureSize{e.width, e.height};
  };
  PresentedSizes p;
  if (probed.lightmapIndex >= 0) p.lightmap = size(probed.lightmapIndex);
  if (probed.skyIndex >= 0) p.sky = size(probed.skyIndex);
  return p;
}

gs::VramLayout checkPresenters(const PresentedSizes& sizes, const player::PlatformConfig& params,
                               const std::string& configPath) {
  try {
    const gs::SkyTexture sky = sizes.sky ? gs::SkyTexture{sizes.sky->width, sizes.sky->height} : gs::SkyTexture{};
    return gs::checkConsole(params.gs, sizes.lightmap.width, sizes.lightmap.height, sky);
  } catch (const gs::GsError& e) {
    throw Error(config::gsConfigMessage(e, configPath));
  }
}

}  // namespace vbim::runs
