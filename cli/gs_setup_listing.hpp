// `vbim config --gs-setup`: the console's VRAM plan and the register writes of each blend draw, for
// a port to compare with its own (docs/porting.md, "GS: upload and in-place blend"). The values come
// from the functions the presenters use (gs::checkParams' plan, gs::blendDrawFor), so the listing
// and a run cannot disagree.
#pragma once

#include <optional>
#include <ostream>

#include "gs/params.hpp"
#include "gs/presenter.hpp"

namespace vbim::cli {

struct PictureSize {
  int width = 0;
  int height = 0;
};

// Writes `vram` (the plan gs::checkParams returned, checked for the sky with gs::checkSkyParams),
// then one Markdown table per blended surface (the lightmap, then the sky if given): the first draw
// of a vsync, which in strip mode covers the first strip.
void writeGsSetup(std::ostream& out, const gs::GsParams& params, const gs::VramLayout& vram, PictureSize lightmap,
                  std::optional<PictureSize> sky);

}  // namespace vbim::cli
