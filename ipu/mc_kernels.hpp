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

struct McKernels {
  // [average][width 16][half-sample case: 2 * vertical + horizontal]
  McPredictFn predict[2][2][4];
  const char* name;
};

const McKernels& scalarMcKernels();

}  // namespace vbim::ipu
