// The hot loops of the decoder behind function pointers: the scalar code in vbim_ipu is the
// reference; vbim_ipu_simd (ipu/simd/) provides Highway versions chosen at run time that must give
// the same bytes (tests/ipu/simd_test.cpp).
#pragma once

#include <cstdint>

#include "ipu/csc.hpp"

namespace vbim::ipu {

// block: 64 coefficients, raster order; rowMask / colMask: bit r / c set if row r / column c may
// hold a non-zero coefficient, except that rowMask bit 8 (kIdctToggleOnly) instead says: F[7][7]
// is +-1 and is the only coefficient of row 7 and column 7 (the usual result of mismatch control,
// ISO/IEC 13818-2 §7.4.4). Writes the 8x8 result clamped to 0..255.
inline constexpr unsigned kIdctToggleOnly = 0x100;
using IdctFn = void (*)(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);

struct Kernels {
  IdctFn idct;
  CscRowFn cscRow;
  const char* name;
};

const Kernels& scalarKernels();

}  // namespace vbim::ipu
