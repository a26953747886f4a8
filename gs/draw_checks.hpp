// The checks of the GS parameters a presenter makes before it runs, without a presenter: the names
// (video mode, COLCLAMP, alpha write, catch-up policy, upload mode and strategy), FIX, strip rows and
// the VRAM plan (gs/vram_plan.hpp). The Presenter calls them, and so does `vbim config`, which has no
// stream to present: the two cannot disagree. Each throws GsError naming the keys.
#pragma once

#include <cstdint>
#include <string>

#include "gs/blend.hpp"
#include "gs/params.hpp"
#include "gs/vram.hpp"
#include "gs/vram_plan.hpp"
#include "runtime/vsync.hpp"

namespace vbim::gs {

enum class CatchUp : std::uint8_t { BlendThrough, HardSkip, PlayLate };
CatchUp catchUpByName(const std::string& name);  // throws GsError

// The settings one by one, as the presenter uses them.
VsyncClock clockFor(const GsParams& p);            // gs.video
ColClamp colclampFor(const GsParams& p);           // gs.colclamp
AlphaWrite alphaFor(const GsParams& p);            // gs.alpha_write
bool checkedStrips(const GsParams& p);             // gs.upload_mode, gs.strip_rows: true for strips
bool checkedMacroblockUploads(const GsParams& p);  // gs.upload_strategy: true for macroblocks

// Every check the presenter makes of its parameters before it runs, for a stream of
// lightmapWidth x lightmapHeight: the names (video, colclamp, alpha write, catch-up, upload mode),
// FIX, strip rows and the VRAM layout. Returns the layout; throws GsError naming the keys. The
// Presenter calls it, and so does `vbim config --check`, which has no stream to present: the two
// cannot disagree.
VramLayout checkParams(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky = {});

// The same checks for the sky presenter of a console whose VRAM plan is `console` (planVram given
// the sky stream's size): the settings, the sky stream within gs.sky_width x gs.sky_height, and its
// draw within the plan's "sky" texture and "sky staging" area. Returns the plan.
VramLayout checkSkyParams(const GsParams& p, const VramLayout& console, int skyWidth, int skyHeight);

// The checks of a console's two presenters, as the player builds them: checkParams for the
// lightmap's, which plans the console's VRAM (returned), given the sky stream's size when there is
// one (sky.width > 0), and then checkSkyParams for the sky's, which draws in that plan.
VramLayout checkConsole(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky = {});

}  // namespace vbim::gs
