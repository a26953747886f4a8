// Highway versions of the decoder's hot loops (inverse DCT, RGB32 colour conversion), with the
// instruction set chosen at run time (no -march=native: one binary runs everywhere and under
// valgrind). Bit-identical to the scalar references in ipu/kernels.cpp and ipu/csc.cpp.
#pragma once

#include <cstdint>

#include "ipu/kernels.hpp"

namespace vbim::ipu {

// IdctKind::Exact (intra).
void idctSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
// IdctKind::Pcsx2 and IdctKind::Libmpeg2, intra (IdctFn) and non-intra (IdctAddFn).
void idctPcsx2Simd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
void idctPcsx2AddSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
void idctLibmpeg2Simd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
void idctLibmpeg2AddSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
void cscRowsRgba32Simd(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                       int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th);
// The kernels of the best target, picked once (plain function pointers, no dispatch per call).
const Kernels& simdKernels();
// The kernels of the best target allowed at this moment, not cached: tests run them on every
// target (vbim::simd::setTargetsForTest). Motion compensation stays simdMcKernels().
Kernels simdKernelsOfCurrentTarget();
// The instruction set the dispatch picked ("AVX2", "AVX3", "SSE4", ...).
const char* simdTargetName();

}  // namespace vbim::ipu
