// The GS checks `vbim play` makes when it builds its presenters (gs::checkConsole), made without a
// run: `vbim config --check/--stream` and `--gs-setup` check a config against a stream's picture
// sizes, or against the smallest lightmap when no stream is given (a config no stream can play).
#pragma once

#include <optional>
#include <string>

#include "gs/setup_listing.hpp"
#include "gs/tiled_blender.hpp"
#include "gs/vram.hpp"
#include "player/platform_config.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::runs {

// The pictures the presenters of a run blend: the lightmap and, if the stream has one, the sky.
// Without a stream, the smallest lightmap a stream can have (one 32x32 page) and no sky.
struct PresentedSizes {
  gs::PictureSize lightmap{gs::kTileHeight, gs::kTileHeight};
  std::optional<gs::PictureSize> sky;
};

// The sizes of the stream on `disc` (its descriptor, as the player probes it), or the default
// without a disc.
PresentedSizes presentedSizes(const streams::StreamDisc* disc);

// gs::checkConsole for these sizes; returns the VRAM plan. A refusal is a vbim::Error said against
// the config file at `configPath` (config::gsConfigMessage), as play says it.
gs::VramLayout checkPresenters(const PresentedSizes& sizes, const player::PlatformConfig& params,
                               const std::string& configPath);

}  // namespace vbim::runs
