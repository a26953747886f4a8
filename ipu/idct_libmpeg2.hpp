// The two integer 8x8 inverse DCTs of the libmpeg2 family, as plain functions of raster-order
// coefficients, written from the arithmetic those decoders perform (facts read, no code copied):
//
// - idctPcsx2: the form PCSX2's IPU uses (IDCT_Block in pcsx2/IPU/IPU_MultiISA.cpp, formerly
//   mpeg2lib/Idct.cpp; derived from libmpeg2 0.4): coefficients as dequantised, row pass rounding
//   with +128 and >> 8, the odd part's sqrt(1/2) factor (181/256) applied after the sum in rows and
//   to pre-shifted terms in columns.
// - idctLibmpeg2: the C IDCT of libmpeg2 0.5.1 (Debian's libmpeg2-4 and `mpeg2dec -c`), which
//   holds coefficients scaled by 16 (4 fractional bits): row pass +2048 and >> 12, the 181/256
//   factor applied to pre-shifted terms in both passes.
//
// Both are separable: 8 row passes, each result stored as a 16-bit integer, then 8 column passes,
// each result stored as a 16-bit integer, so both truncate to 16 bits between the passes, and
// PCSX2's row pass can overflow 32 bits on extreme (legal but never encoded) blocks; both effects
// are reproduced here with defined arithmetic (two's complement), so the result is the same bits
// the reference decoders compute on every input. They differ from each other in the last bit on
// a few percent of blocks (tests/ipu/idct_libmpeg2_test.cpp), and both differ from the exact
// transform of ipu/idct.hpp. Which one the console's IPU computes is not known from a hardware
// capture (docs/timing/ipu.md#idct).
#pragma once

#include <cstdint>

namespace vbim::ipu {

// The 8x8 block's 64 results before any clip to pixels: for an intra block the decoders clamp
// them to 0..255; for a non-intra block they are the residual added to the prediction (then
// clamped). `coeffs` holds 64 dequantised, saturated coefficients in raster order (F[v][u] at
// 8v + u, each in [-2048, 2047]); `out` may alias `coeffs`.
void idctPcsx2(const std::int16_t* coeffs, std::int16_t* out);
void idctLibmpeg2(const std::int16_t* coeffs, std::int16_t* out);

// Non-intra blocks whose only coded coefficient is the first in scan order (F[0][0], plus the
// mismatch toggle of F[7][7] in MPEG-2) take a shortcut in both reference decoders: every residual
// sample is (F[0][0] + 4) >> 3 and F[7][7] is ignored, except when F[0][0] & 7 == 4 (the value is a
// tie that the toggle decides), where the full transform runs. True if the shortcut applies.
inline bool nonIntraDcShortcut(int dc) {
  return (dc & 7) != 4;
}
inline int nonIntraDcResidual(int dc) {
  return (dc + 4) >> 3;
}

}  // namespace vbim::ipu
