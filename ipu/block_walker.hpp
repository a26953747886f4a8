// A slow, plain walk of an intra picture's blocks for the per-stage known-answer vectors
// (docs/porting.md, "Per-stage vectors"): every block's DC size and differential and AC run/level
// pairs as the bitstream codes them, its 64 quantised coefficients QF, and its 64 dequantised
// coefficients F (saturated, mismatch control applied) as IDEC hands them to the IDCT. It reads
// the slices with the decoder's own VLC tables and slice-syntax pieces (ipu/vlc_tables.hpp,
// ipu/slice_syntax.hpp) but keeps every intermediate value, which the hot slice decoder
// (ipu/slice_decoder.cpp) folds away. assembleIntraPicture() puts the IDCT of every block back
// into a frame store: tests/ipu/block_walker_test.cpp checks that this is the decoder's picture
// bit for bit, so the vectors show what the decoder computes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ipu/frame_store.hpp"
#include "ipu/kernels.hpp"

namespace vbim::ipu {

struct RunLevel {
  int run = 0;
  int level = 0;  // signed
  bool escape = false;
};

struct WalkedBlock {
  int dcSize = 0;            // dct_dc_size_luminance / _chrominance
  int dcDifferential = 0;    // dct_dc_differential as a signed value (0 when dcSize is 0)
  std::vector<RunLevel> ac;  // in bitstream order, up to end of block
  // Natural (raster) order, F[v][u] at 8v + u. quantised[0] is the predicted DC (the predictor plus
  // the differential); the others are the signed levels placed by the scan.
  std::array<std::int16_t, 64> quantised{};
  // §7.4: the inverse quantisation, saturation to [-2048, 2047] and (MPEG-2) mismatch control.
  std::array<std::int16_t, 64> dequantised{};
};

struct WalkedMacroblock {
  int address = 0;  // mbY * mbWidth + mbX
  int mbX = 0;
  int mbY = 0;
  int quantiserScaleCode = 0;
  bool fieldDct = false;
  std::size_t bits = 0;               // bits of the macroblock (the first of a slice includes the slice header)
  std::array<WalkedBlock, 6> blocks;  // Y0 Y1 Y2 Y3 Cb Cr
};

struct WalkedPicture {
  int width = 0;
  int height = 0;
  int mbWidth = 0;
  int mbHeight = 0;
  bool mpeg1 = false;
  int intraDcPrecision = 0;
  bool qScaleType = false;
  bool intraVlcFormat = false;
  bool alternateScan = false;
  std::array<std::uint8_t, 64> intraMatrix{};  // raster order
  std::vector<WalkedMacroblock> macroblocks;   // in bitstream order
};

// Walks picture `index` (0 the first) of `bytes`, with the headers before it (a picture as the EE
// hands it to the IPU, or an elementary stream). An intra frame picture only; false with `error` naming the byte offset
// and what was found for anything else (a P, B or field picture, a corrupt code, a skipped macroblock, a missing
// slice).
bool walkIntraPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index = 0);

// The IDCT's 64 results for dequantised coefficients, before any clip: Pcsx2 and Libmpeg2 as
// ipu/idct_libmpeg2.hpp computes them, Exact as idctSignedUnclipped (ipu/idct.hpp).
void idctResult(IdctKind kind, const std::int16_t* coeffs, std::int16_t* out);
// An intra block's samples as IDEC writes them: idctResult clamped to 0..255.
void idctSamples(IdctKind kind, const std::int16_t* coeffs, std::uint8_t* out);

// Every block's idctSamples placed where the picture's macroblock puts it (field DCT included).
FrameStore assembleIntraPicture(const WalkedPicture& picture, IdctKind kind);

}  // namespace vbim::ipu
