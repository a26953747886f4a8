#include "ipu/simd/mc_kernels.hpp"

#include <cstddef>
#include <cstdint>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ipu/simd/mc_kernels.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace vbim::ipu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET != HWY_SCALAR
// The four-sample interpolation (a + b + c + d + 2) >> 2 in bytes: with ab = (a + b + 1) >> 1 and
// cd = (c + d + 1) >> 1, (ab + cd + 1) >> 1 is one too large exactly when a + b or c + d is odd
// and ab + cd is odd (write a + b = 2p + e, c + d = 2q + f and compare the two floors), so
// subtracting ((a ^ b) | (c ^ d)) & (ab ^ cd) & 1 gives the exact result.
template <class D, class V>
HWY_INLINE V average4(D d, V a, V b, V c, V e) {
  const V ab = hn::AverageRound(a, b);
  const V ce = hn::AverageRound(c, e);
  const V odd = hn::And(hn::And(hn::Or(hn::Xor(a, b), hn::Xor(c, e)), hn::Xor(ab, ce)), hn::Set(d, 1));
  return hn::Sub(hn::AverageRound(ab, ce), odd);
}

// The rows of one block prediction in the kernel's half-sample case: src(r, dx) is the vector of
// source row r (0..rows) from column dx (0 or 1), put(r, p) stores output row r (averaged with
// what is there for the B-picture average).
template <int Case, class D, class Src, class Put>
HWY_INLINE void predictRows(D d, Src&& src, Put&& put, int rows) {
  if constexpr (Case == 0) {
    for (int r = 0; r < rows; ++r) put(r, src(r, 0));
  } else if constexpr (Case == 1) {
    for (int r = 0; r < rows; ++r) put(r, hn::AverageRound(src(r, 0), src(r, 1)));
  } else if constexpr (Case == 2) {
    auto above = src(0, 0);
    for (int r = 0; r < rows; ++r) {
      const auto below = src(r + 1, 0);
      put(r, hn::AverageRound(above, below));
      above = below;
    }
  } else {
    auto a = src(0, 0);
    auto b = src(0, 1);
    for (int r = 0; r < rows; ++r) {
      const auto c = src(r + 1, 0);
      const auto e = src(r + 1, 1);
      put(r, average4(d, a, b, c, e));
      a = c;
      b = e;
    }
  }
}

template <bool Average, int Width, int Case>
HWY_INLINE void predictPlane(std::uint8_t* HWY_RESTRICT dst, std::ptrdiff_t dstStride,
                             const std::uint8_t* HWY_RESTRICT src, std::ptrdiff_t srcStride, int rows) {
  const hn::FixedTag<std::uint8_t, Width> d;
  predictRows<Case>(
      d, [&](int r, int dx) { return hn::LoadU(d, src + r * srcStride + dx); },
      [&](int r, hn::Vec<decltype(d)> p) {
        std::uint8_t* o = dst + r * dstStride;
        if constexpr (Average) p = hn::AverageRound(hn::LoadU(d, o), p);
        hn::StoreU(p, d, o);
      },
      rows);
}

template <bool Average, int Width, int Case>
void predictImpl(std::uint8_t* HWY_RESTRICT dst, std::ptrdiff_t dstStride, const std::uint8_t* HWY_RESTRICT src,
                 std::ptrdiff_t srcStride, int rows) {
  predictPlane<Average, Width, Case>(dst, dstStride, src, srcStride, rows);
}

// Cb and Cr together: a row of each in the low and high 8 bytes of one 16-byte vector (the two
// planes have the same stride and the same vector), so the chroma costs one set of operations.
template <bool Average, int Case>
HWY_INLINE void predictChromaPair(const McBlock& b) {
  const hn::FixedTag<std::uint8_t, 16> d;
  const hn::Half<decltype(d)> dh;
  const std::uint8_t* HWY_RESTRICT scb = b.scb;
  const std::uint8_t* HWY_RESTRICT scr = b.scr;
  std::uint8_t* HWY_RESTRICT dcb = b.dcb;
  std::uint8_t* HWY_RESTRICT dcr = b.dcr;
  const std::ptrdiff_t ss = b.scStride, ds = b.dcStride;
  predictRows<Case>(
      d,
      [&](int r, int dx) {
        const std::ptrdiff_t o = r * ss + dx;
        return hn::Combine(d, hn::LoadU(dh, scr + o), hn::LoadU(dh, scb + o));
      },
      [&](int r, hn::Vec<decltype(d)> p) {
        const std::ptrdiff_t o = r * ds;
        if constexpr (Average) p = hn::AverageRound(hn::Combine(d, hn::LoadU(dh, dcr + o), hn::LoadU(dh, dcb + o)), p);
        hn::StoreU(hn::LowerHalf(dh, p), dh, dcb + o);
        hn::StoreU(hn::UpperHalf(dh, p), dh, dcr + o);
      },
      b.rows / 2);
}

template <bool Average, int LumaCase, int ChromaCase>
void blockImpl(const McBlock& b) {
  predictPlane<Average, 16, LumaCase>(b.dy, b.dyStride, b.sy, b.syStride, b.rows);
  predictChromaPair<Average, ChromaCase>(b);
}

template <bool Average, int Width>
void fill(McPredictFn (&out)[4]) {
  out[0] = predictImpl<Average, Width, 0>;
  out[1] = predictImpl<Average, Width, 1>;
  out[2] = predictImpl<Average, Width, 2>;
  out[3] = predictImpl<Average, Width, 3>;
}

template <bool Average, int LumaCase>
void fillBlock(McBlockFn (&out)[4]) {
  out[0] = blockImpl<Average, LumaCase, 0>;
  out[1] = blockImpl<Average, LumaCase, 1>;
  out[2] = blockImpl<Average, LumaCase, 2>;
  out[3] = blockImpl<Average, LumaCase, 3>;
}

template <bool Average>
void fillBlocks(McBlockFn (&out)[4][4]) {
  fillBlock<Average, 0>(out[0]);
  fillBlock<Average, 1>(out[1]);
  fillBlock<Average, 2>(out[2]);
  fillBlock<Average, 3>(out[3]);
}

// This target's kernels, picked once (a dispatch per block would cost more than a small block).
McKernels mcTable() {
  McKernels k{};
  fill<false, 8>(k.predict[0][0]);
  fill<false, 16>(k.predict[0][1]);
  fill<true, 8>(k.predict[1][0]);
  fill<true, 16>(k.predict[1][1]);
  fillBlocks<false>(k.block[0]);
  fillBlocks<true>(k.block[1]);
  k.name = "highway";
  return k;
}
#else
McKernels mcTable() {
  return scalarMcKernels();
}
#endif

}  // namespace vbim::ipu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "runtime/simd/targets.hpp"

namespace vbim::ipu {

VBIM_SIMD_EXPORT(mcTable);

McKernels simdMcKernelsOfCurrentTarget() {
  return VBIM_SIMD_DISPATCH(mcTable)();
}

const McKernels& simdMcKernels() {
  static const McKernels k = simdMcKernelsOfCurrentTarget();
  return k;
}

}  // namespace vbim::ipu
#endif
