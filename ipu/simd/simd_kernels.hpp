// Highway versions of the decoder's hot loops (inverse DCT, RGB32 colour conversion), with the
// instruction set chosen at run time (no -march=native: one binary runs everywhere and under
// valgrind). Bit-identical to the scalar reference in ipu/idct.cpp and ipu/csc.cpp.
#pragma once

#include <cstdint>

#include "ipu/kernels.hpp"

namespace vbim::ipu {

void idctSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
void cscRowsRgba32Simd(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                       int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th);
const Kernels& simdKernels();
// The instruction set the dispatch picked ("AVX2", "AVX3", "SSE4", ...).
const char* simdTargetName();

}  // namespace vbim::ipu
