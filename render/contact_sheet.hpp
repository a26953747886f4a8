// The day on one page: the rendered frames as thumbnails in a grid, each framed by what the player
// was doing since the previous one (red: the lightmap was behind, i.e. stalled; orange: catching up;
// grey: on time), and under the grid a strip over the whole run, one column per slice of vsyncs, in
// the same colours, with a white tick at every thumbnail's vsync.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/image.hpp"

namespace vbim::render {

enum class Moment : std::uint8_t { OnTime, CatchUp, Stall };

struct SheetTile {
  std::int64_t vsync = 0;
  Rgba8Image picture;
  Moment moment = Moment::OnTime;  // the worst state since the previous tile
};

// `states`: one per vsync of the run (index = vsync), may be empty (no strip).
Rgba8Image contactSheet(const std::vector<SheetTile>& tiles, const std::vector<Moment>& states, int columns,
                        int thumbWidth);

// Box-filter downscale to `width` (height keeps the aspect ratio).
Rgba8Image downscale(const Rgba8Image& in, int width);

}  // namespace vbim::render
