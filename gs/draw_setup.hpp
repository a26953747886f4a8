// The register writes of the in-place blend draw, as a console sends them: one A+D GIFtag, then one
// qword per register write (64-bit value + register address), ending with the two vertices of the
// textured SPRITE. The list is the model's single source for both the cost of the draw's setup on
// the GIF (kBlendDrawSetupQwords) and the values docs/porting.md tells a port to write.
//
// Every register the blend's result depends on is written, not left to whatever the game's own
// rendering set before: the frame buffer and texture, the blend and its clamp, the pixel tests,
// the scissor and the offset, per-pixel alpha-blend and alpha-correction controls.
// Register addresses and field layouts: the GS User's Manual as summarised by ps2tek (T-GS) and
// ps2sdk gs_gp.h (SDK-GS); addresses as PCSX2's GIF_A_D_REG_* list them (P-GS).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "gs/params.hpp"
#include "gs/vram.hpp"

namespace vbim::gs {

struct GsRegister {
  std::string_view name;
  std::uint8_t address;  // the A+D register address
  std::string_view why;
};

// In the order they are sent. UV and XYZ2 appear twice: the sprite's two corners (XYZ2 kicks).
inline constexpr std::array kBlendDrawRegisters{
    GsRegister{"TEXFLUSH", 0x3F, "the staging texture was just written by an IMAGE transfer: flush the texture cache"},
    GsRegister{"FRAME_1", 0x4C, "draw into the lightmap itself (the in-place blend); FBMSK keeps its alpha if asked"},
    GsRegister{"ZBUF_1", 0x4E, "ZMSK = 1: the sprite writes no Z"},
    GsRegister{"TEST_1", 0x47, "no alpha or destination-alpha test; ZTE = 1 with ZTST = ALWAYS, so no Z is read"},
    GsRegister{"TEX0_1", 0x06, "the staging texture, PSMCT32, RGBA, MODULATE"},
    GsRegister{"TEX1_1", 0x14, "nearest filtering, no mipmaps: texel (x, y) lands on pixel (x, y)"},
    GsRegister{"CLAMP_1", 0x08, "CLAMP in U and V: no texel from the opposite edge"},
    GsRegister{"ALPHA_1", 0x42, "Cv = (Cs - Cd) * FIX / 128 + Cd: A = Cs, B = Cd, C = FIX, D = Cd"},
    GsRegister{"PABE", 0x49, "0: blend every pixel, whatever its source alpha"},
    GsRegister{"FBA_1", 0x4A, "0: the written alpha is not forced"},
    GsRegister{"COLCLAMP", 0x46, "clamp (or wrap) the blended colour to 0..255"},
    GsRegister{"SCISSOR_1", 0x40, "the lightmap's rectangle"},
    GsRegister{"XYOFFSET_1", 0x18, "0: vertices are given in the lightmap's own coordinates"},
    GsRegister{"PRIM", 0x00, "SPRITE, TME = 1, ABE = 1, FST = 1 (UV texel coordinates)"},
    GsRegister{"RGBAQ", 0x01, "0x80 in each channel: MODULATE passes the texel through unchanged"},
    GsRegister{"UV", 0x03, "first corner's texel, 12.4 fixed point"},
    GsRegister{"XYZ2", 0x05, "first corner, 12.4 fixed point"},
    GsRegister{"UV", 0x03, "second corner's texel"},
    GsRegister{"XYZ2", 0x05, "second corner: draws the sprite"},
};

// The A+D GIFtag, then one qword per register write.
inline constexpr std::int64_t kBlendDrawSetupQwords = 1 + static_cast<std::int64_t>(kBlendDrawRegisters.size());

// The 16-bit path (gs.texture_format = ct16, gs/blend16.hpp) writes three more, before PRIM: how the
// RGB16 texels' alpha bit becomes As, and the GS's dither. The 32-bit draw leaves them alone.
inline constexpr std::array kSixteenBitRegisters{
    GsRegister{"TEXA", 0x3B, "TA0 = 0x80 for RGB16 alpha bit 0, TA1 = 0x40 for 1, AEM = 0: As as the IPU's RGB32"},
    GsRegister{"DIMX", 0x44, "the 4x4 dither matrix DTHE adds before the top 5 bits of each channel are kept"},
    GsRegister{"DTHE", 0x45, "1 for the blend, 0 for the copy of a first or snapped frame (FIX = 0x80)"},
};
// Where they go in the draw: before PRIM (kBlendDrawRegisters' 14th write).
inline constexpr std::size_t kSixteenBitInsertAt = 13;
inline constexpr std::int64_t kBlendDrawSetupQwords16 =
    kBlendDrawSetupQwords + static_cast<std::int64_t>(kSixteenBitRegisters.size());

// What the values depend on: where the buffers are and which rows this sprite covers.
struct BlendDraw {
  VramRegion frame;                   // the texture blended into: the lightmap or the sky (FRAME_1.FBP)
  VramRegion texture;                 // its staging texture (TEX0_1.TBP0)
  const VramRegion* depth = nullptr;  // the Z buffer ZBUF_1 names, if any (never read or written)
  int width = 0;                      // the blended picture: the whole lightmap, or the sky stream's
  int height = 0;                     // picture in the sky texture's top-left corner (SCISSOR_1)
  int y0 = 0;                         // the sprite's rows in it
  int y1 = 0;
  int textureRow0 = 0;     // the staging texture's row that lands on y0
  int fix = 0x40;          // ALPHA_1.FIX
  bool clamp = true;       // COLCLAMP.CLAMP
  bool keepAlpha = false;  // FRAME_1.FBMSK = 0xFF000000 (PSMCT16: 0x80000000, the alpha bit)
  bool dither = false;     // DTHE, for a PSMCT16 frame (the 16-bit path) drawn with FIX < 0x80
};

struct RegisterWrite {
  GsRegister reg;
  std::uint64_t value;
};

using BlendDrawSetup = std::array<RegisterWrite, kBlendDrawRegisters.size()>;

// The values of kBlendDrawRegisters for one sprite. Throws GsError unless the frame and texture are
// both PSMCT32 or both PSMCT16.
BlendDrawSetup blendDrawSetup(const BlendDraw& draw);
// For a PSMCT16 frame, the values of kSixteenBitRegisters (TEXA, DIMX, DTHE = draw.dither).
std::array<RegisterWrite, kSixteenBitRegisters.size()> sixteenBitSetup(const BlendDraw& draw);
// Every write of the draw in the order sent: blendDrawSetup, and for a PSMCT16 frame the
// sixteenBitSetup writes before PRIM (kBlendDrawSetupQwords16 - 1 writes).
std::vector<RegisterWrite> blendDrawWrites(const BlendDraw& draw);

// The rows one blend draw covers (and its staging area holds): gs.strip_rows, at most the picture's
// height, in strip mode; the whole picture in full upload mode.
int drawRows(const GsParams& params, int height);

// The two textures a console blends in place, each from its own staging area (planVram).
enum class BlendSurface : std::uint8_t {
  Lightmap,  // "lightmap" from "staging"
  Sky,       // "sky" from "sky staging": the sky stream's picture in the sky texture's top-left corner
};
const char* blendSurfaceName(BlendSurface surface);  // "lightmap", "sky"

// The sprite over rows [y0, y1) of the surface's width x height picture as the presenter draws it
// with `params` in the layout planVram gave: in strip mode the staging texture holds just this
// strip, in full mode the whole picture; with gs.texture_format = ct16, dithered. Throws GsError if the layout has no
// such surface, or the picture or the rows do not fit it.
BlendDraw blendDrawFor(const VramLayout& vram, const GsParams& params, BlendSurface surface, int width, int height,
                       int y0, int y1);

}  // namespace vbim::gs
