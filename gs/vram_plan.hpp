// The console's VRAM plan for a lightmap (and a sky) blended in place: frame buffers, Z, the lightmap,
// its upload staging area, the sky texture and the sky's staging area, placed page by page
// (gs/vram.hpp). No presenter and no simulated time: `vbim config` plans with it as the presenters do.
#pragma once

#include <string>
#include <vector>

#include "gs/params.hpp"
#include "gs/vram.hpp"

namespace vbim::gs {

// The size of the sky stream a console shows beside the lightmap (width 0: none, or not known).
struct SkyTexture {
  int width = 0;
  int height = 0;
};

// The VRAM a game using this presenter would have: frame buffers, Z, the lightmap, the upload
// staging area (the whole frame, or one strip) and the sky texture (gs.sky_width x gs.sky_height).
// Given the sky stream's size, also the sky's own staging area ("sky staging", sized as the
// lightmap's), and the sky stream must fit the sky texture. Throws GsError if it does not fit.
VramLayout planVram(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky = {});

// The sky stream must fit the texture VRAM keeps for it (gs.sky_width x gs.sky_height): throws
// GsError naming those keys. Width 0: no sky stream, nothing to check.
void checkSkyFits(const GsParams& p, SkyTexture sky);

// The PSM of the blended textures and their staging areas (gs.texture_format); throws GsError.
Psm texturePsm(const GsParams& p);

// The gs.* keys that decide the VRAM layout (a GsError from planVram names them).
const std::vector<std::string>& vramLayoutKeys();

}  // namespace vbim::gs
