// The prediction loops of motion compensation (ISO/IEC 13818-2 §7.6.4, §7.6.7) behind function
// pointers, reached through Kernels::mc (ipu/kernels.hpp; the residual add is the IDCT's add
// kernel there): the scalar code here is the reference; ipu/simd/mc_kernels.hpp provides Highway versions chosen at run
// time that must give the same bytes (tests/ipu/mc_kernels_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace vbim::ipu {

// Predicts a block of `rows` rows (width fixed by the kernel: 16 or 8 samples) from `src`, the
// reference sample at the vector's whole-sample position, with the half-sample interpolation of
// the kernel's case: none, horizontal (a + b + 1) >> 1, vertical, or both (a + b + c + d + 2) >> 2.
// Reads one column to the right and one row below where the case interpolates. The averaging
// kernels then store (dst + p + 1) >> 1 (§7.6.7), the others p.
using McPredictFn = void (*)(std::uint8_t* dst, std::ptrdiff_t dstStride, const std::uint8_t* src,
                             std::ptrdiff_t srcStride, int rows);

// One prediction of a macroblock (its 16 luma columns, or one field's rows of them, or a 16x8
// half) with its two 8-wide chroma blocks: destinations, and the reference samples at the
// vectors' whole-sample positions (luma, and chroma with the halved vector), each plane's
// half-sample case chosen by the kernel. `rows` luma rows, rows / 2 chroma rows.
struct McBlock {
  std::uint8_t* dy;
  std::uint8_t* dcb;
  std::uint8_t* dcr;
  std::ptrdiff_t dyStride;
  std::ptrdiff_t dcStride;
  const std::uint8_t* sy;
  const std::uint8_t* scb;
  const std::uint8_t* scr;
  std::ptrdiff_t syStride;
  std::ptrdiff_t scStride;
  int rows;
};
// The three planes of one prediction in one call: one indirect call per prediction instead of
// three, and the Highway kernels predict Cb and Cr together (one 16-byte vector holds a row of
// each), halving the chroma arithmetic. Same bytes as predict[] on each plane.
using McBlockFn = void (*)(const McBlock& b);

struct McKernels {
  // [average][width 16][half-sample case: 2 * vertical + horizontal]
  McPredictFn predict[2][2][4];
  // [average][luma case][chroma case]
  McBlockFn block[2][4][4];
  const char* name;
};

const McKernels& scalarMcKernels();

}  // namespace vbim::ipu
