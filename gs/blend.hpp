// The GS alpha blend used to fold a decoded video frame into the lightmap in place (T-GS
// AlphaBlending; docs/hardware.md#alpha-blending): ALPHA_1 = (A = Cs, B = Cd, C = FIX, D = Cd), so per colour
// channel
//     Cv = (((Cs - Cd) * FIX) >> 7) + Cd
// on 9-bit signed values with an arithmetic shift (floor, as PCSX2's software renderer does [E]),
// then COLCLAMP: clamp to 0..255, or keep the low 8 bits (wrap). FIX = 0x80 is 1.0 (a copy).
// The written alpha is As (the texture's alpha passed through MODULATE with vertex alpha 0x80), or
// the old Ad when FRAME.FBMSK masks the alpha byte.
//
// The scalar functions here are the reference: SIMD kernels (gs/simd/blend_simd.hpp) must match them
// bit for bit, and the tests check that exhaustively.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "gs/hash_chain.hpp"
#include "gs/image_compare.hpp"

namespace vbim::gs {

enum class ColClamp : std::uint8_t { Clamp, Wrap };
enum class AlphaWrite : std::uint8_t { Source, Keep };

struct BlendSpec {
  std::uint8_t fix = 0x40;
  ColClamp colclamp = ColClamp::Clamp;
  AlphaWrite alpha = AlphaWrite::Source;
  // The 16-bit path (gs/blend16.hpp): PSMCT16 texels, blended by blend16Rect, never by the kernels
  // below; `dither` is DTHE (DIMX added before the top 5 bits are kept).
  bool psmct16 = false;
  bool dither = false;
  bool operator==(const BlendSpec&) const = default;
};

// Checks FIX (the 8-bit ALPHA.FIX field, bits 32-39) and builds a spec; throws GsError otherwise.
BlendSpec makeBlendSpec(std::int64_t fix, ColClamp colclamp = ColClamp::Clamp, AlphaWrite alpha = AlphaWrite::Source);

// One channel. cs, cd in 0..255, fix in 0..255. C++20 defines >> on negative values as arithmetic.
constexpr int blendChannel(int cs, int cd, int fix, ColClamp c) {
  const int v = (((cs - cd) * fix) >> 7) + cd;
  return c == ColClamp::Clamp ? std::clamp(v, 0, 255) : (v & 0xFF);
}

// True if blending cd toward cs leaves it unchanged: floor((cs - cd) * fix / 128) == 0, that is
// 0 <= (cs - cd) * fix < 128. Below the target a texel can stop short (up to ceil(128/fix) - 1
// levels); above it, every step moves by at least one, so it always reaches cs.
constexpr bool isFixedPoint(int cs, int cd, int fix) {
  const int p = (cs - cd) * fix;
  return p >= 0 && p < 128;
}

// The largest change one blend step can make to a channel whose distance to the target is
// |cs - cd| = diff: ceil(diff * fix / 128), capped at 255 (the channel's range).
constexpr int maxStep(int diff, int fix) {
  return std::min(255, (diff * fix + 127) / 128);
}

// The widest band below the target where repeated blending stalls: ceil(128 / fix) - 1 (fix > 0).
constexpr int stallBand(int fix) {
  return fix <= 0 ? 255 : std::min(255, (128 + fix - 1) / fix - 1);
}

// A span of RGBA8 pixels (4 bytes each), blended in place: dst = blend(src, dst).
using BlendSpanFn = void (*)(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec);
// The same, returning the largest per-byte change it made (0: the span was already at its fixed
// point). This is the pop metric and the convergence test in one pass.
using BlendSpanDeltaFn = int (*)(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec);
// blendDelta over `rows` spans of `pixels` each, the rows dstStride and srcStride bytes apart (a
// tile of the lightmap): one call and one reduction of the change per tile instead of per row.
// `settled` (null, or a mask of rows <= 32 bits wide) lets a tile be blended row by row as it
// converges: a row whose bit is set is at its fixed point for this src and spec (spanAtFixedPoint)
// and is skipped, and each blended row's bit is set when the blend left it at its fixed point. The
// caller clears the mask whenever src or spec changes. Bytes and the returned change are the same as
// without the mask: a skipped row would not have changed.
using BlendRectDeltaFn = int (*)(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src,
                                 std::size_t srcStride, std::size_t pixels, std::size_t rows, const BlendSpec& spec,
                                 std::uint32_t* settled);

// A tile row of an image blended and folded into the frame hash's chain in one pass (gs/hash_chain.hpp):
// `rows` whole image rows of `pixels` (dst and src rows follow each other, 4 * pixels bytes apart),
// cut into tiles of `tilePixels` columns (the last may be narrower). For tile t, exactly what
// blendRectDelta(tile t, settled + t) does: rows marked in settled[t] are skipped, blended rows left
// at their fixed point are marked, and the largest change it made is maxed into delta[t]. Then, if
// chain is not null, the rows' bytes after the blend are folded into *chain in order (4 * pixels *
// rows bytes: a whole number of words when pixels is even, which the caller ensures, or this is the
// image's end). The SIMD kernels interleave the two row by row, which the result cannot tell.
using BlendHashRowsFn = void (*)(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, std::size_t rows,
                                 std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled, int* delta,
                                 HashChain* chain);

struct BlendKernels {
  const char* name;
  BlendSpanFn blend;
  BlendSpanDeltaFn blendDelta;
  BlendRectDeltaFn blendRectDelta;
  CompareRectFn compareRect;  // the lag's per-byte difference (gs/image_compare.hpp), same SIMD target
  BlendHashRowsFn blendHashRows;
};

void blendSpanScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec);
int blendSpanDeltaScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec);
int blendRectDeltaScalar(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                         std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled);
// The reference: each tile with blendRectDeltaScalar, then the rows into the chain.
void blendHashRowsScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, std::size_t rows,
                         std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled, int* delta,
                         HashChain* chain);

// True when blending the span toward src once more would change no byte: every colour channel is
// at its fixed point (isFixedPoint), and alpha equals As (AlphaWrite::Source; Ad kept never moves).
// A sufficient test: in Wrap mode with FIX > 128 a step of exactly 256 also changes nothing.
bool spanAtFixedPoint(const std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec);

// The largest Cs - Cd (Cs >= Cd) that is a fixed point at this FIX: 127 / FIX, or 255 for FIX 0
// (which never moves anything). SIMD kernels test fixed points with it.
constexpr int fixedPointBand(int fix) {
  return fix == 0 ? 255 : 127 / fix;
}

// The reference kernels ("scalar").
const BlendKernels& scalarKernels();

}  // namespace vbim::gs
