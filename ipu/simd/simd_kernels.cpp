#include "ipu/simd/simd_kernels.hpp"

#include <cstddef>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ipu/simd/simd_kernels.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "ipu/csc.hpp"

// Basis of the 1-D transform as used by ipu/idct.cpp: B(k, n) = 2^14 for k = 0, else
// W_j * sign with cos((2n+1) k pi / 16) = sign * cos(j pi / 16).
#ifndef VBIM_IPU_SIMD_BASIS
#define VBIM_IPU_SIMD_BASIS
namespace vbim::ipu::simd_detail {
struct Basis {
  alignas(64) std::int32_t b[8][8]{};       // [k][n]
  alignas(64) std::int32_t toggle[8][8]{};  // [y][x]: B(7, y) * B(7, x), the F[7][7] = 1 term
  // Row pass by pairs of columns: [p][2x + j] = B(2p + j, x), as 16-bit lanes for a pairwise
  // multiply-add against (F[v][2p], F[v][2p + 1]).
  alignas(64) std::int16_t colPairs[4][16]{};
  // Column pass by pairs of rows: [y][k] = B(va, y) in the low and B(vb, y) in the high 16 bits, for
  // the row pairs (va, vb) = (0, 2), (4, 6), (1, 3), (5, 7) (even rows, then odd rows).
  alignas(64) std::int32_t rowPairs[8][4]{};
  constexpr Basis() {
    constexpr std::int32_t kW[8] = {23170, 22725, 21407, 19266, 16384, 12873, 8867, 4520};
    for (int k = 0; k < 8; ++k)
      for (int n = 0; n < 8; ++n) {
        if (k == 0) {
          b[k][n] = 16384;
          continue;
        }
        int m = ((2 * n + 1) * k) % 32;  // angle m pi / 16
        if (m > 16) m = 32 - m;          // cos is even around 2 pi
        b[k][n] = m < 8 ? kW[m] : (m == 8 ? 0 : -kW[16 - m]);
      }
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) toggle[y][x] = b[7][y] * b[7][x];
    for (int p = 0; p < 4; ++p)
      for (int x = 0; x < 8; ++x)
        for (int j = 0; j < 2; ++j) colPairs[p][2 * x + j] = static_cast<std::int16_t>(b[2 * p + j][x]);
    constexpr int kPairs[4][2] = {{0, 2}, {4, 6}, {1, 3}, {5, 7}};
    for (int y = 0; y < 8; ++y)
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t lo = static_cast<std::uint16_t>(b[kPairs[k][0]][y]);
        const std::uint32_t hi = static_cast<std::uint16_t>(b[kPairs[k][1]][y]);
        rowPairs[y][k] = static_cast<std::int32_t>(lo | (hi << 16));
      }
  }
};
// Built by the compiler: no guard check on every call of the hot kernels.
inline constexpr Basis kBasis{};
inline const Basis& basis() {
  return kBasis;
}
}  // namespace vbim::ipu::simd_detail
#endif

HWY_BEFORE_NAMESPACE();
namespace vbim::ipu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET != HWY_SCALAR
// Rows below R and column pairs below CP (the rest are zero), with 16 x 16 -> 32-bit pairwise
// multiply-adds (pmaddwd) in both passes. Row pass: c[v][x] = sum_u F[v][u] B(u, x), exact in 32
// bits (|c| < 2048 * 122,426 < 2^28). c = ch * 2^14 + cl with |ch| < 2^14 and cl in [-2^13, 2^13),
// so both halves fit 16-bit lanes for the column pass; H = sum ch B and L = sum cl B stay below
// 2^31, and out = (H + (L >> 14) + 2^16) >> 17 == floor((sum_v c B + 2^30) / 2^31), the scalar
// result. The mismatch toggle alone in row 7 / column 7 adds +-B(7, y) B(7, x) to L, unless the
// block is read whole (R = 8, CP = 4), where F[7][7] is part of the sums.
template <int R, int CP>
HWY_INLINE void idctMaddImpl(const std::int16_t* block, bool toggle, std::uint8_t* dst, int stride) {
  const hn::CappedTag<std::int32_t, 8> d;
  const hn::Repartition<std::int16_t, decltype(d)> d16;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const std::size_t N = hn::Lanes(d);
  const auto& P = simd_detail::basis().colPairs;
  const auto& Q = simd_detail::basis().rowPairs;
  const auto& T = simd_detail::basis().toggle;
  using V = hn::Vec<decltype(d)>;
  const std::int32_t sign = (toggle && !(R == 8 && CP == 4)) ? block[63] : 0;
  for (std::size_t x0 = 0; x0 < 8; x0 += N) {
    V ch[8], cl[8];
    for (int v = 0; v < R; ++v) {
      V acc = hn::Zero(d), acc1 = hn::Zero(d);
      for (int p = 0; p < CP; ++p) {
        std::int32_t pair;
        std::memcpy(&pair, &block[8 * v + 2 * p], 4);
        acc = hn::ReorderWidenMulAccumulate(d, hn::BitCast(d16, hn::Set(d, pair)), hn::LoadU(d16, &P[p][2 * x0]), acc,
                                            acc1);
      }
      acc = hn::RearrangeToOddPlusEven(acc, acc1);
      ch[v] = hn::ShiftRight<14>(hn::Add(acc, hn::Set(d, 1 << 13)));
      cl[v] = hn::Sub(acc, hn::ShiftLeft<14>(ch[v]));
    }
    for (int v = R; v < 8; ++v) ch[v] = cl[v] = hn::Zero(d);
    // Row pairs as 16-bit lanes: (c[va][x], c[vb][x]) in each 32-bit lane.
    const V lowHalf = hn::Set(d, 0xFFFF);
    auto pairUp = [&](const V* c, int va, int vb) {
      return hn::BitCast(d16, hn::Or(hn::And(c[va], lowHalf), hn::ShiftLeft<16>(c[vb])));
    };
    static constexpr int kPairRows[4][2] = {{0, 2}, {1, 3}, {4, 6}, {5, 7}};
    static constexpr int kPairIndex[4] = {0, 2, 1, 3};  // position of each in rowPairs[y]
    hn::Vec<decltype(d16)> hp[4], lp[4];
    // Row pairs (0, 2) and (1, 3) always; (4, 6) and (5, 7) only for R = 8.
    constexpr int kUsed = R == 8 ? 4 : 2;
    for (int k = 0; k < kUsed; ++k) {
      hp[k] = pairUp(ch, kPairRows[k][0], kPairRows[k][1]);
      lp[k] = pairUp(cl, kPairRows[k][0], kPairRows[k][1]);
    }
    for (int y = 0; y < 4; ++y) {
      // Second accumulators: on x86 pmaddwd leaves them zero; other targets may put products there.
      V he = hn::Set(d, 1 << 16), ho = hn::Zero(d), le = hn::Zero(d), lo = hn::Zero(d);
      V he1 = hn::Zero(d), ho1 = hn::Zero(d), le1 = hn::Zero(d), lo1 = hn::Zero(d);
      for (int k = 0; k < kUsed; ++k) {
        const auto q = hn::BitCast(d16, hn::Set(d, Q[y][kPairIndex[k]]));
        if (kPairRows[k][0] & 1) {
          ho = hn::ReorderWidenMulAccumulate(d, hp[k], q, ho, ho1);
          lo = hn::ReorderWidenMulAccumulate(d, lp[k], q, lo, lo1);
        } else {
          he = hn::ReorderWidenMulAccumulate(d, hp[k], q, he, he1);
          le = hn::ReorderWidenMulAccumulate(d, lp[k], q, le, le1);
        }
      }
      he = hn::RearrangeToOddPlusEven(he, he1);
      ho = hn::RearrangeToOddPlusEven(ho, ho1);
      le = hn::RearrangeToOddPlusEven(le, le1);
      lo = hn::RearrangeToOddPlusEven(lo, lo1);
      V lt = hn::Add(le, lo), lb = hn::Sub(le, lo);
      if (sign > 0) {
        lt = hn::Add(lt, hn::LoadU(d, &T[y][x0]));
        lb = hn::Add(lb, hn::LoadU(d, &T[7 - y][x0]));
      } else if (sign < 0) {
        lt = hn::Sub(lt, hn::LoadU(d, &T[y][x0]));
        lb = hn::Sub(lb, hn::LoadU(d, &T[7 - y][x0]));
      }
      const V top = hn::ShiftRight<17>(hn::Add(hn::Add(he, ho), hn::ShiftRight<14>(lt)));
      const V bottom = hn::ShiftRight<17>(hn::Add(hn::Sub(he, ho), hn::ShiftRight<14>(lb)));
      hn::StoreU(hn::DemoteTo(d8, top), d8, dst + static_cast<std::ptrdiff_t>(y) * stride + x0);
      hn::StoreU(hn::DemoteTo(d8, bottom), d8, dst + static_cast<std::ptrdiff_t>(7 - y) * stride + x0);
    }
  }
}

// The transform on the smallest rectangle of row pairs and column pairs holding every non-zero
// coefficient (2, 4 or 8 rows; 2, 4 or 8 columns).
template <int R>
HWY_INLINE void idctRows(const std::int16_t* block, unsigned cols, bool toggle, std::uint8_t* dst, int stride) {
  if (cols <= 0x3) return idctMaddImpl<R, 1>(block, toggle, dst, stride);
  if (cols <= 0xF) return idctMaddImpl<R, 2>(block, toggle, dst, stride);
  idctMaddImpl<R, 4>(block, toggle, dst, stride);
}

void idctImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  const bool toggle = (rowMask & 0x100) != 0;
  const unsigned rows = rowMask & 0xFF, cols = colMask & 0xFF;
  if (rows <= 0x3) return idctRows<2>(block, cols, toggle, dst, stride);
  if (rows <= 0xF) return idctRows<4>(block, cols, toggle, dst, stride);
  idctRows<8>(block, cols, toggle, dst, stride);
}
#else
// One-lane fallback target: no 16-bit pairs in a 32-bit lane; the scalar reference.
void idctImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  scalarKernels().idctOf(IdctKind::Exact).copy(block, rowMask, colMask, dst, stride);
}
#endif

// One chroma line's RGB32 rows (1 or 2 luma lines) with the PS2 matrix, in 16-bit lanes:
// lum = (0x95 * max(0, Y - 16)) >> 6, then (lum + term + 1) >> 1 clamped to 0..255; alpha 0x80;
// SETTH. The chroma terms are computed once per chroma sample, at half resolution, and doubled in
// registers for the two pixels (and the two lines) they cover: (a << 4) * (b << 6) >> 16 ==
// (a * b) >> 6 exactly for |a| < 2^11 and the coefficients below (the scalar code's floor shift).
// rc = Cr term of R, gc = both terms of G, bc = Cb term of B.
void cscRowsImpl(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                 int width, std::uint8_t* rgba, int rgbaStride, int th0, int th1) {
  int x = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<std::int16_t> d;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const hn::Half<decltype(d)> dh;
  const hn::Rebind<std::uint8_t, decltype(dh)> dh8;
  const hn::Repartition<std::int32_t, decltype(d)> d32;
  const int N = static_cast<int>(hn::Lanes(d));
  const auto kRcr = hn::Set(dh, 0xCC << 6), kGcr = hn::Set(dh, -0x68 << 6);
  const auto kGcb = hn::Set(dh, -0x32 << 6), kBcb = hn::Set(dh, 0x102 << 6);
  const auto c128 = hn::Set(dh, 128);
  const auto lowHalf = hn::Set(d32, 0xFFFF);
  // (t0, t1, ...) -> (t0, t0, t1, t1, ...): each term widened to 32 bits holds itself twice.
  auto doubled = [&](hn::Vec<decltype(dh)> t) {
    const auto w = hn::PromoteTo(d32, t);
    return hn::BitCast(d, hn::Or(hn::And(w, lowHalf), hn::ShiftLeft<16>(w)));
  };
  const auto kY = hn::Set(d, 0x95 << 6);
  const auto one = hn::Set(d, 1);
  const auto vTh0 = hn::Set(d, static_cast<std::int16_t>(th0)), vTh1 = hn::Set(d, static_cast<std::int16_t>(th1));
  const auto a80 = hn::Set(d, 0x80), a40 = hn::Set(d, 0x40);
  for (; x + N <= width; x += N) {
    const auto vb = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(dh, hn::LoadU(dh8, cb + x / 2)), c128));
    const auto vr = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(dh, hn::LoadU(dh8, cr + x / 2)), c128));
    const auto rTerm = doubled(hn::MulHigh(vr, kRcr));
    const auto gTerm = doubled(hn::Add(hn::MulHigh(vr, kGcr), hn::MulHigh(vb, kGcb)));
    const auto bTerm = doubled(hn::MulHigh(vb, kBcb));
    for (int row = 0; row < rows; ++row) {
      const std::uint8_t* yl = y + static_cast<std::ptrdiff_t>(row) * yStride;
      std::uint8_t* out = rgba + static_cast<std::ptrdiff_t>(row) * rgbaStride + 4 * static_cast<std::ptrdiff_t>(x);
      const auto yy = hn::PromoteTo(d, hn::SaturatedSub(hn::LoadU(d8, yl + x), hn::Set(d8, 16)));
      const auto lum = hn::Add(hn::MulHigh(hn::ShiftLeft<4>(yy), kY), one);
      const auto r = hn::ShiftRight<1>(hn::Add(lum, rTerm));
      const auto g = hn::ShiftRight<1>(hn::Add(lum, gTerm));
      const auto b = hn::ShiftRight<1>(hn::Add(lum, bTerm));
      if (th0 <= 0 && th1 <= 0) {
        // No SETTH thresholds: alpha is 0x80 everywhere and the saturating narrow does the clamp.
        hn::StoreInterleaved4(hn::DemoteTo(d8, r), hn::DemoteTo(d8, g), hn::DemoteTo(d8, b), hn::Set(d8, 0x80), d8,
                              out);
        continue;
      }
      const auto zero = hn::Zero(d), k255 = hn::Set(d, 255);
      const auto rc = hn::Min(hn::Max(r, zero), k255), gc = hn::Min(hn::Max(g, zero), k255);
      const auto bc = hn::Min(hn::Max(b, zero), k255);
      // SETTH on the clamped values: all below TH0 -> 0; else all below TH1 -> alpha 0x40.
      const auto m = hn::Max(hn::Max(rc, gc), bc);
      const auto cleared = m < vTh0;
      const auto alpha = hn::IfThenZeroElse(cleared, hn::IfThenElse(m < vTh1, a40, a80));
      hn::StoreInterleaved4(hn::DemoteTo(d8, hn::IfThenZeroElse(cleared, rc)),
                            hn::DemoteTo(d8, hn::IfThenZeroElse(cleared, gc)),
                            hn::DemoteTo(d8, hn::IfThenZeroElse(cleared, bc)), hn::DemoteTo(d8, alpha), d8, out);
    }
  }
#endif
  for (; x < width; ++x) {
    const int cbv = cb[x >> 1] - 128, crv = cr[x >> 1] - 128;
    const int rTerm = (0xCC * crv) >> 6, gTerm = ((-0x68 * crv) >> 6) + ((-0x32 * cbv) >> 6),
              bTerm = (0x102 * cbv) >> 6;
    for (int row = 0; row < rows; ++row) {
      const std::uint8_t yv = y[row * yStride + x];
      const int lum = ((0x95 * (yv > 16 ? yv - 16 : 0)) >> 6) + 1;
      auto clamp = [](int v) { return v < 0 ? 0 : (v > 255 ? 255 : v); };
      const int r = clamp((lum + rTerm) >> 1), g = clamp((lum + gTerm) >> 1), b = clamp((lum + bTerm) >> 1);
      const int m = r > g ? (r > b ? r : b) : (g > b ? g : b);
      std::uint8_t* o = rgba + static_cast<std::ptrdiff_t>(row) * rgbaStride + 4 * static_cast<std::ptrdiff_t>(x);
      if (m < th0) {
        o[0] = o[1] = o[2] = o[3] = 0;
      } else {
        o[0] = static_cast<std::uint8_t>(r);
        o[1] = static_cast<std::uint8_t>(g);
        o[2] = static_cast<std::uint8_t>(b);
        o[3] = static_cast<std::uint8_t>(m < th1 ? 0x40 : 0x80);
      }
    }
  }
}

}  // namespace vbim::ipu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vbim::ipu {

HWY_EXPORT(idctImpl);
HWY_EXPORT(cscRowsImpl);

void idctSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  HWY_DYNAMIC_DISPATCH(idctImpl)(block, rowMask & 0x1FF, colMask & 0xFF, dst, stride);
}

void cscRowsRgba32Simd(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                       int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th) {
  HWY_DYNAMIC_DISPATCH(cscRowsImpl)(y, yStride, rows, cb, cr, width, rgba, rgbaStride, th.th0, th.th1);
}

const Kernels& simdKernels() {
  // The libmpeg2-family kinds and the exact kind's non-intra entry: the scalar references for now.
  const Kernels& s = scalarKernels();
  static const Kernels k{{s.idct[0], s.idct[1], {idctSimd, s.idct[2].add}}, cscRowsRgba32Simd, "highway"};
  return k;
}

const char* simdTargetName() {
  const std::int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  return hwy::TargetName(targets & -targets);  // the best target has the lowest bit
}

}  // namespace vbim::ipu
#endif
