// The exact-rounded 8x8 inverse DCT (ipu.idct = "exact"; the default is PCSX2's, in
// ipu/idct_libmpeg2.hpp): integer, separable, exact for a DC-only block, accurate to
// IEEE 1180-1990 (tests/ipu/idct_test.cpp runs that standard's procedure). Integer
// arithmetic only, so every compiler and every SIMD path gives the same bits; this scalar code is
// the reference the fast paths are tested against.
//
// Each 1-D pass is the direct even/odd form of x(n) = sum_u C(u) F(u) cos((2n+1)u pi/16) with the
// constants W_k = round(2^14 * sqrt(2) * cos(k pi/16)), so W_4 = 2^14 and the DC term is exact.
// Rows are summed exactly in 32 bits, columns in 64 bits with one rounding at the end, so the
// result is the exact integer floor((sum F(v,u) W(u,x) W(v,y) + 2^30) / 2^31): no overflow for any
// input in the saturated range [-2048, 2047], and every evaluation order gives the same bits.
#pragma once

#include <cstdint>

namespace vbim::ipu {

inline constexpr std::int32_t kIdctW1 = 22725;
inline constexpr std::int32_t kIdctW2 = 21407;
inline constexpr std::int32_t kIdctW3 = 19266;
inline constexpr std::int32_t kIdctW5 = 12873;
inline constexpr std::int32_t kIdctW6 = 8867;
inline constexpr std::int32_t kIdctW7 = 4520;

// Inverse-transforms `block` (64 coefficients, raster order, each in [-2048, 2047]) and writes the
// 8x8 result, clamped to 0..255, to dst with the given stride. rowMask has bit r set if row r may
// hold a non-zero coefficient (0xFF when unknown). The block is left unchanged.
void idctScalar(const std::int16_t* block, unsigned rowMask, std::uint8_t* dst, int stride);

// The same transform with signed output clipped to [-256, 255] (IEEE 1180-1990 test interface).
void idctSigned(const std::int16_t* block, std::int16_t* out);
// The same transform's signed result before any clip (|result| < 2^14 for any input in range): the
// residual of a non-intra block. rowMask as for idctScalar.
void idctSignedUnclipped(const std::int16_t* block, unsigned rowMask, std::int16_t* out);

// The exact transform of a block holding only F[0][0] = dc and F[7][7] = f77 (0, or 1 after
// mismatch control) is the constant (dc + 4) >> 3 when f77 is 0, or when the F[7][7] term, below
// 2^29 in magnitude against the 2^31 of one output step, cannot carry the rounding across a step:
// (dc + 4) & 7 in [2, 6] (tests/ipu/idct_test.cpp checks every dc). The non-intra add kernel of
// IdctKind::Exact then adds exactIdctConstant(dc) to the prediction.
inline bool exactIdctIsConstant(int dc, int f77) {
  const int r = (dc + 4) & 7;
  return f77 == 0 || (f77 == 1 && r >= 2 && r <= 6);
}
inline int exactIdctConstant(int dc) {
  return (dc + 4) >> 3;
}

// The value every sample of a block takes when only F[0][0] is non-zero: (dc + 4) >> 3, clamped.
inline std::uint8_t idctDcValue(int dc) {
  const int v = (dc + 4) >> 3;
  return static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
}

}  // namespace vbim::ipu
