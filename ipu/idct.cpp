#include "ipu/idct.hpp"

#include <cstddef>
#include <cstring>

namespace vbim::ipu {
namespace {

// The row pass keeps its sums whole (no rounding: at most 2048 * 7.47 * 2^14 < 2^28), the column
// pass sums in 64 bits and rounds once: out = floor((sum_u sum_v F W W + 2^30) / 2^31). With no
// intermediate rounding the result is one exact integer expression, so any evaluation order (the
// SIMD paths, the sparse shortcuts) gives the same bits.
constexpr int kColShift = 31;

inline std::uint8_t clampPixel(std::int64_t v) {
  return static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
}

// One row: 8 coefficients in, 8 values with 8 fractional bits (scaled by sqrt(8)) out.
inline void rowPass(const std::int16_t* f, std::int32_t* out) {
  const std::int32_t f0 = f[0], f1 = f[1], f2 = f[2], f3 = f[3], f4 = f[4], f5 = f[5], f6 = f[6], f7 = f[7];
  if ((f1 | f2 | f3 | f4 | f5 | f6 | f7) == 0) {
    const std::int32_t v = f0 * 16384;
    for (int n = 0; n < 8; ++n) out[n] = v;
    return;
  }
  const std::int32_t t0 = (f0 + f4) * 16384;
  const std::int32_t t1 = (f0 - f4) * 16384;
  const std::int32_t t2 = kIdctW2 * f2 + kIdctW6 * f6;
  const std::int32_t t3 = kIdctW6 * f2 - kIdctW2 * f6;
  const std::int32_t e0 = t0 + t2, e3 = t0 - t2, e1 = t1 + t3, e2 = t1 - t3;
  const std::int32_t o0 = kIdctW1 * f1 + kIdctW3 * f3 + kIdctW5 * f5 + kIdctW7 * f7;
  const std::int32_t o1 = kIdctW3 * f1 - kIdctW7 * f3 - kIdctW1 * f5 - kIdctW5 * f7;
  const std::int32_t o2 = kIdctW5 * f1 - kIdctW1 * f3 + kIdctW7 * f5 + kIdctW3 * f7;
  const std::int32_t o3 = kIdctW7 * f1 - kIdctW5 * f3 + kIdctW3 * f5 - kIdctW1 * f7;
  out[0] = (e0 + o0);
  out[7] = (e0 - o0);
  out[1] = (e1 + o1);
  out[6] = (e1 - o1);
  out[2] = (e2 + o2);
  out[5] = (e2 - o2);
  out[3] = (e3 + o3);
  out[4] = (e3 - o3);
}

// The column pass and the output stage, shared by the pixel and the signed entry points:
// store(row, column, value) receives each result before clamping.
template <class Store>
void idctCore(const std::int16_t* block, unsigned rowMask, Store&& store) {
  std::int32_t r[64];
  for (int v = 0; v < 8; ++v) {
    if (rowMask & (1u << v)) {
      rowPass(block + static_cast<std::ptrdiff_t>(8 * v), r + static_cast<std::ptrdiff_t>(8 * v));
    } else {
      for (int n = 0; n < 8; ++n) r[8 * v + n] = 0;
    }
  }
  if ((rowMask & 0xFE) == 0) {
    // Only the first row: every output row equals (r0 * 2^14 + 2^(kColShift-1)) >> kColShift.
    for (int c = 0; c < 8; ++c) {
      const std::int64_t v = (static_cast<std::int64_t>(r[c]) + (1 << (kColShift - 15))) >> (kColShift - 14);
      // == (r0 * 2^14 + 2^30) >> 31
      for (int y = 0; y < 8; ++y) store(y, c, v);
    }
    return;
  }
  constexpr std::int64_t kRound = std::int64_t{1} << (kColShift - 1);
  for (int c = 0; c < 8; ++c) {
    const std::int64_t f0 = r[c], f1 = r[8 + c], f2 = r[16 + c], f3 = r[24 + c], f4 = r[32 + c], f5 = r[40 + c],
                       f6 = r[48 + c], f7 = r[56 + c];
    const std::int64_t t0 = (f0 + f4) * 16384 + kRound;
    const std::int64_t t1 = (f0 - f4) * 16384 + kRound;
    const std::int64_t t2 = kIdctW2 * f2 + kIdctW6 * f6;
    const std::int64_t t3 = kIdctW6 * f2 - kIdctW2 * f6;
    const std::int64_t e0 = t0 + t2, e3 = t0 - t2, e1 = t1 + t3, e2 = t1 - t3;
    const std::int64_t o0 = kIdctW1 * f1 + kIdctW3 * f3 + kIdctW5 * f5 + kIdctW7 * f7;
    const std::int64_t o1 = kIdctW3 * f1 - kIdctW7 * f3 - kIdctW1 * f5 - kIdctW5 * f7;
    const std::int64_t o2 = kIdctW5 * f1 - kIdctW1 * f3 + kIdctW7 * f5 + kIdctW3 * f7;
    const std::int64_t o3 = kIdctW7 * f1 - kIdctW5 * f3 + kIdctW3 * f5 - kIdctW1 * f7;
    store(0, c, (e0 + o0) >> kColShift);
    store(7, c, (e0 - o0) >> kColShift);
    store(1, c, (e1 + o1) >> kColShift);
    store(6, c, (e1 - o1) >> kColShift);
    store(2, c, (e2 + o2) >> kColShift);
    store(5, c, (e2 - o2) >> kColShift);
    store(3, c, (e3 + o3) >> kColShift);
    store(4, c, (e3 - o3) >> kColShift);
  }
}

}  // namespace

void idctScalar(const std::int16_t* block, unsigned rowMask, std::uint8_t* dst, int stride) {
  rowMask &= 0xFF;
  if (rowMask == 0) {
    for (int y = 0; y < 8; ++y) std::memset(dst + static_cast<std::ptrdiff_t>(y) * stride, 0, 8);
    return;
  }
  idctCore(block, rowMask, [dst, stride](int y, int x, std::int64_t v) { dst[y * stride + x] = clampPixel(v); });
}

void idctSigned(const std::int16_t* block, std::int16_t* out) {
  idctCore(block, 0xFF, [out](int y, int x, std::int64_t v) {
    out[8 * y + x] = static_cast<std::int16_t>(v < -256 ? -256 : (v > 255 ? 255 : v));
  });
}

void idctSignedUnclipped(const std::int16_t* block, unsigned rowMask, std::int16_t* out) {
  idctCore(block, rowMask & 0xFF,
           [out](int y, int x, std::int64_t v) { out[8 * y + x] = static_cast<std::int16_t>(v); });
}

}  // namespace vbim::ipu
