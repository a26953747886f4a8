// The 16-bit lightmap path (gs.texture_format = "ct16"): the IPU writes RGB16 (IDEC OFM = 1, with its
// own ordered dither, DTE = 1), uploaded into a PSMCT16 staging texture and blended into a PSMCT16
// lightmap with the GS's dither on (DTHE = 1, DIMX below). The model keeps each 16-bit texel as the
// RGBA8 pixel the GS expands it to, so the frame hash and the tiles work unchanged:
//     R, G, B = the 5-bit field << 3 (low bits zero), A = 0x80 if bit 15 is set, else 0.
//
// Per vsync and colour channel (PCSX2 GSDrawScanline: the 16-bit frame buffer read back with
// `<< 3`, WriteFrame adds DIMX[y & 3][x & 3] to the blended value, masks it to 8 bits without
// COLCLAMP, saturates to 0..255 and keeps the top 5 bits [E]):
//     Cv = (((Cs - Cd) * FIX) >> 7) + Cd + DIMX[y & 3][x & 3]   (without DTHE: no DIMX term)
//     Cv = Cv & 0xFF (COLCLAMP = 0 only); clamp to 0..255; stored Cv & 0xF8
// and the written alpha is bit 7 of As (FBMSK = 0x80000000 keeps the old one). The source texel
// is the staging texture's: the IPU's RGB16 pixel expanded by TEXA (TA0 = 0x80 for A = 0, TA1 =
// 0x40 for A = 1, AEM = 0), so As is the RGB32 alpha the IPU would have written (0x80, or 0x40
// under SETTH TH1). The copy of a first or snapped frame (FIX = 0x80) is drawn without DTHE: a
// dithered copy would move already 5-bit values.
//
// Why the 32-bit model cannot stand in for it: every stored value is a multiple of 8 and the
// dither moves the rounding point per pixel, so both the steps and the point where the blend stops
// differ (at FIX = 0x40 a channel one 5-bit level below its target never reaches it).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "gs/blend.hpp"
#include "runtime/image.hpp"

namespace vbim::gs {

// DIMX as games set it (gsKit's and Sony's sample code: GS_SET_DIMX(4,2,5,3, 0,6,1,7, 5,3,4,2,
// 1,7,0,6), 3-bit two's complement), indexed [y & 3][x & 3].
inline constexpr std::array<std::array<int, 4>, 4> kDimx{
    {{-4, 2, -3, 3}, {0, -2, 1, -1}, {-3, 3, -4, 2}, {1, -1, 0, -2}}};
// The register: entry [y][x] in bits 16y + 4x .. + 2 (ps2sdk gs_gp.h GS_SET_DIMX).
std::uint64_t dimxRegister();
// TEXA: TA0 = 0x80 (bits 0-7), AEM = 0 (bit 15), TA1 = 0x40 (bits 32-39) (gs_gp.h GS_SET_TEXA).
inline constexpr std::uint64_t kTexa16 = 0x80 | std::uint64_t{0x40} << 32;

// The IPU's RGB16 dither (DTE = 1), indexed [y & 3][x & 3] of the picture: the matrix of ipu/csc.cpp
// (P-IPU IPUdither.cpp), which a test checks against ipu::convertToRgb16.
inline constexpr std::array<std::array<int, 4>, 4> kIpuDither{
    {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}}};

// The staging texture of the 16-bit path for a decoded frame (RGB32, as the IPU's OFM = 0 output):
// the IPU's RGB16 of it (DTE = 1) as the GS reads it through TEXA, expanded as above. `out` is
// resized to the frame's size.
void staging16FromRgb32(const Rgba8Image& frame, Rgba8Image& out);

// One channel: cs, cd multiples of 8 (expanded 5-bit values), `dither` the DIMX entry (0 without DTHE).
constexpr int blend16Channel(int cs, int cd, int fix, int dither, ColClamp c) {
  int v = (((cs - cd) * fix) >> 7) + cd + dither;
  if (c == ColClamp::Wrap) v &= 0xFF;
  return std::clamp(v, 0, 255) & 0xF8;
}

// Blends `rows` rows of `pixels` expanded texels of `src` into `dst` (strides in bytes), the first
// pixel at (x0, y0) of the texture (for DIMX), with spec.fix, spec.colclamp, spec.alpha and
// spec.dither. Returns the largest per-byte change. The reference; there is no SIMD path.
int blend16Rect(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                std::size_t pixels, std::size_t rows, int x0, int y0, const BlendSpec& spec);

// The 16-bit texel of an expanded pixel (bits 0-4 R, 5-9 G, 10-14 B, 15 A), as VRAM holds it.
constexpr std::uint16_t texel16(const std::uint8_t* rgba) {
  return static_cast<std::uint16_t>((rgba[0] >> 3) | (rgba[1] >> 3) << 5 | (rgba[2] >> 3) << 10 | (rgba[3] >> 7) << 15);
}

}  // namespace vbim::gs
