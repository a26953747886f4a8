#include "ipu/simd/simd_kernels.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ipu/simd/simd_kernels.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "ipu/csc.hpp"
#include "ipu/idct_libmpeg2.hpp"
#include "ipu/simd/mc_kernels.hpp"

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

// The libmpeg2-family IDCTs (ipu/idct_libmpeg2.cpp) with one row per vector: lane n holds output n
// of the row pass, computed from the row's coefficients paired as 16-bit (x0, x4), (x2, x6),
// (x1, x7), (x3, x5) and multiplied with per-lane constants (pmaddwd: each pair's sum is exact in
// 32 bits, every later sum wraps as the scalar code's wrap32). Even lanes give a0..a3 (with the
// bias), odd lanes b0, b3 (signs included) or u +- v, which the 181/256 step then takes.
struct Mpeg2Tables {
  alignas(64) std::int16_t even04[16]{};  // [2n + j]: lane n's factors of (x0, x4)
  alignas(64) std::int16_t even26[16]{};  // ... of (x2, x6)
  alignas(64) std::int16_t odd17[16]{};   // ... of (x1, x7)
  alignas(64) std::int16_t odd35[16]{};   // ... of (x3, x5)
  alignas(64) std::int32_t rotated[8]{};  // -1 in lanes 1, 2, 5, 6: the 181/256 step applies
  alignas(64) std::int32_t negated[8]{};  // -1 in lanes 5, 6: that step's result is subtracted
  alignas(16) std::uint8_t pairs[16]{};   // the row's bytes reordered to x0 x4 x2 x6 x1 x7 x3 x5
  // The same for two rows in one 256-bit vector (mpeg2RowPair): in each 128-bit block the first four
  // lanes of even04, even26, odd17, odd35, and pairs. Full-width tables: GCC 12 builds a duplicated
  // 128-bit load as a load and a vinserti128, which takes the shuffle port.
  alignas(32) std::int16_t quad[4][16]{};
  alignas(32) std::uint8_t pairs2[32]{};
  // [libmpeg2 0.5.1's form][F[7][7] = +1, -1, no toggle]: the row pass of row 7 when the mismatch
  // toggle is its only coefficient, as mpeg2Row computes it (same steps, in constexpr integers), so
  // the kernel need not load row 7 the parser has just written; zeros when there is no toggle.
  // Each value is held in the high 16 bits, where the column pass pairs it with row 1.
  alignas(64) std::int32_t toggleRow[2][3][8]{};
  constexpr Mpeg2Tables() {
    constexpr int kW1 = 2841, kW2 = 2676, kW3 = 2408, kW5 = 1609, kW6 = 1108, kW7 = 565;
    // a0, a1, a2, a3 as factors of x0, x4, x2, x6; lanes 4..7 mirror 3..0.
    constexpr int kEven[4][4] = {
        {2048, 2048, kW2, kW6}, {2048, -2048, kW6, -kW2}, {2048, -2048, -kW6, kW2}, {2048, 2048, -kW2, -kW6}};
    // Lanes 0..7 as factors of x1, x7, x3, x5: b0, u + v, u - v, b3, -b3, u - v, u + v, -b0 with
    // o0 = W7 x7 + W1 x1, o1 = W7 x1 - W1 x7, o2 = W3 x3 + W5 x5, o3 = W3 x5 - W5 x3,
    // b0 = o0 + o2, b3 = o1 + o3, u = o0 - o2, v = o1 - o3.
    constexpr int kOdd[8][4] = {{kW1, kW7, kW3, kW5},
                                {kW1 + kW7, kW7 - kW1, kW5 - kW3, -kW5 - kW3},
                                {kW1 - kW7, kW7 + kW1, -kW3 - kW5, kW3 - kW5},
                                {kW7, -kW1, -kW5, kW3},
                                {-kW7, kW1, kW5, -kW3},
                                {kW1 - kW7, kW7 + kW1, -kW3 - kW5, kW3 - kW5},
                                {kW1 + kW7, kW7 - kW1, kW5 - kW3, -kW5 - kW3},
                                {-kW1, -kW7, -kW3, -kW5}};
    for (int n = 0; n < 8; ++n) {
      const int* e = kEven[n < 4 ? n : 7 - n];
      even04[2 * n] = static_cast<std::int16_t>(e[0]);
      even04[2 * n + 1] = static_cast<std::int16_t>(e[1]);
      even26[2 * n] = static_cast<std::int16_t>(e[2]);
      even26[2 * n + 1] = static_cast<std::int16_t>(e[3]);
      odd17[2 * n] = static_cast<std::int16_t>(kOdd[n][0]);
      odd17[2 * n + 1] = static_cast<std::int16_t>(kOdd[n][1]);
      odd35[2 * n] = static_cast<std::int16_t>(kOdd[n][2]);
      odd35[2 * n + 1] = static_cast<std::int16_t>(kOdd[n][3]);
      rotated[n] = (n == 1 || n == 2 || n == 5 || n == 6) ? -1 : 0;
      negated[n] = (n == 5 || n == 6) ? -1 : 0;
    }
    for (int form = 0; form < 2; ++form) {
      for (int neg = 0; neg < 2; ++neg) {
        const int x7 = (neg ? -1 : 1) * (form ? 16 : 1);  // libmpeg2 0.5.1 holds coefficients x16
        for (int n = 0; n < 8; ++n) {
          int o = kOdd[n][1] * x7;
          if (n == 1 || n == 2 || n == 5 || n == 6) o = form ? (o >> 8) * 181 : (o * 181) >> 8;
          if (n == 5 || n == 6) o = -o;
          const int x = ((form ? 2048 : 128) + o) >> (form ? 12 : 8);
          toggleRow[form][neg][n] =
              static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint16_t>(x)) << 16);
        }
      }
    }
    constexpr int kOrder[8] = {0, 4, 2, 6, 1, 7, 3, 5};
    for (int i = 0; i < 8; ++i) {
      pairs[2 * i] = static_cast<std::uint8_t>(2 * kOrder[i]);
      pairs[2 * i + 1] = static_cast<std::uint8_t>(2 * kOrder[i] + 1);
    }
    for (int i = 0; i < 16; ++i) {
      quad[0][i] = even04[i % 8];
      quad[1][i] = even26[i % 8];
      quad[2][i] = odd17[i % 8];
      quad[3][i] = odd35[i % 8];
      pairs2[i] = pairs2[16 + i] = pairs[i];
    }
  }
};
inline constexpr Mpeg2Tables kMpeg2{};
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

// One row of the libmpeg2-family row pass (Pcsx2: PCSX2's IPU form, else libmpeg2 0.5.1's) into
// out[0..7] as 32-bit results; the decoders store their low 16 bits, which is all the column pass
// reads of them.
template <bool Pcsx2>
HWY_INLINE void mpeg2Row(const std::int16_t* row, std::int32_t* out) {
  const hn::CappedTag<std::int32_t, 8> d;
  const hn::Repartition<std::int16_t, decltype(d)> d16;
  const hn::Repartition<std::uint8_t, decltype(d)> d8;
  const std::size_t N = hn::Lanes(d);
  const auto& T = simd_detail::kMpeg2;
  auto v = hn::LoadDup128(d16, row);
  if constexpr (!Pcsx2) v = hn::ShiftLeft<4>(v);  // libmpeg2 0.5.1 holds coefficients x16 (in 16 bits)
  const auto ordered = hn::BitCast(d, hn::TableLookupBytes(hn::BitCast(d8, v), hn::LoadDup128(d8, T.pairs)));
  const auto p04 = hn::BitCast(d16, hn::Broadcast<0>(ordered));
  const auto p26 = hn::BitCast(d16, hn::Broadcast<1>(ordered));
  const auto p17 = hn::BitCast(d16, hn::Broadcast<2>(ordered));
  const auto p35 = hn::BitCast(d16, hn::Broadcast<3>(ordered));
  constexpr int kShift = Pcsx2 ? 8 : 12;
  const auto bias = hn::Set(d, Pcsx2 ? 128 : 2048), k181 = hn::Set(d, 181);
  for (std::size_t n0 = 0; n0 < 8; n0 += N) {
    auto e1 = hn::Zero(d), o1 = hn::Zero(d);
    auto e = hn::ReorderWidenMulAccumulate(d, p04, hn::LoadU(d16, T.even04 + 2 * n0), hn::Zero(d), e1);
    e = hn::RearrangeToOddPlusEven(hn::ReorderWidenMulAccumulate(d, p26, hn::LoadU(d16, T.even26 + 2 * n0), e, e1), e1);
    e = hn::Add(e, bias);
    auto o = hn::ReorderWidenMulAccumulate(d, p17, hn::LoadU(d16, T.odd17 + 2 * n0), hn::Zero(d), o1);
    o = hn::RearrangeToOddPlusEven(hn::ReorderWidenMulAccumulate(d, p35, hn::LoadU(d16, T.odd35 + 2 * n0), o, o1), o1);
    const auto r = Pcsx2 ? hn::ShiftRight<8>(hn::Mul(o, k181)) : hn::Mul(hn::ShiftRight<8>(o), k181);
    o = hn::IfThenElse(hn::MaskFromVec(hn::LoadU(d, T.rotated + n0)), r, o);
    const auto neg = hn::LoadU(d, T.negated + n0);
    o = hn::Sub(hn::Xor(o, neg), neg);
    // Not truncated here: the column pass takes each result's low 16 bits into its 16-bit pairs.
    hn::StoreU(hn::ShiftRight<kShift>(hn::Add(e, o)), d, out + n0);
  }
}

// Rows a and b as 16-bit pairs: the low 16 bits of a's lane in the even, of b's in the odd 16-bit
// lane (one shift and a pblendw on x86). The 16-bit truncation the decoders' block store does
// between the passes comes with it.
template <class D, class V = hn::Vec<D>>
HWY_INLINE hn::Vec<hn::Repartition<std::int16_t, D>> pairOf(D /*d*/, V a, V b) {
  const hn::Repartition<std::int16_t, D> d16;
  return hn::OddEven(hn::BitCast(d16, hn::ShiftLeft<16>(b)), hn::BitCast(d16, a));
}

// ka * a + kb * b for each pair (a, b): pmaddwd on x86, exact in 32 bits (|k| < 2^15, so no pair
// reaches its one overflow case), as the scalar code's sum of two 16 x 16 products is.
template <std::int32_t Ka, std::int32_t Kb, class D, class V16>
HWY_INLINE hn::Vec<D> madd(D d, V16 pair) {
  const hn::Repartition<std::int16_t, D> d16;
  constexpr auto k = static_cast<std::int32_t>(static_cast<std::uint32_t>(Ka & 0xFFFF) |
                                               (static_cast<std::uint32_t>(Kb & 0xFFFF) << 16));
  auto s1 = hn::Zero(d);
  const auto s0 = hn::ReorderWidenMulAccumulate(d, pair, hn::BitCast(d16, hn::Set(d, k)), hn::Zero(d), s1);
  return hn::RearrangeToOddPlusEven(s0, s1);
}

// The column pass on columns c0 .. c0 + N - 1 of the row results rows[0 .. R - 1] (rows R and below
// are zero, except row 7 in t7 when T7, R < 8: the mismatch toggle alone in row 7): out[y] = the 16-bit
// result of output row y, before any clip. Sums wrap as the scalar code's, so their order is free.
// Every product pair of the scalar pass is one pairwise multiply-add on rows paired as 16-bit
// lanes (x1, x7), (x3, x5), (x2, x6), (x0, x4): pmaddwd where 32-bit multiplies (pmulld, two uops
// and a long latency on Intel) took each product alone. With no row 4, x0 is paired with the
// constant 32, so that 2048 * 32 is the pass's bias 65536.
template <bool Pcsx2, int R, bool T7, class D, class V = hn::Vec<D>>
HWY_INLINE void mpeg2Columns(D d, const V* rows, const std::int32_t* t7, std::size_t c0, V* out) {
  constexpr int kW1 = 2841, kW2 = 2676, kW3 = 2408, kW5 = 1609, kW6 = 1108, kW7 = 565;
  const hn::Repartition<std::int16_t, D> d16;
  const auto x = [&](int r) { return rows[r]; };
  const auto k = [&](int c) { return hn::Set(d, c); };
  const V x0 = x(0), x1 = x(1);
  V a0, a1, a2, a3, b0, b3, u, v, b1, b2;
  if constexpr (R > 4) {
    const auto p04 = pairOf(d, x0, x(4)), p26 = pairOf(d, x(2), x(6));
    const auto p17 = pairOf(d, x1, x(7)), p35 = pairOf(d, x(3), x(5));
    const V e0 = hn::Add(madd<2048, 2048>(d, p04), k(65536));
    const V e1 = hn::Add(madd<2048, -2048>(d, p04), k(65536));
    const V e2 = madd<kW2, kW6>(d, p26), e3 = madd<kW6, -kW2>(d, p26);
    const V o0 = madd<kW1, kW7>(d, p17), o1 = madd<kW7, -kW1>(d, p17);
    const V o2 = madd<kW3, kW5>(d, p35), o3 = madd<-kW5, kW3>(d, p35);
    a0 = hn::Add(e0, e2);
    a1 = hn::Add(e1, e3);
    a2 = hn::Sub(e1, e3);
    a3 = hn::Sub(e0, e2);
    b0 = hn::Add(o0, o2);
    b3 = hn::Add(o1, o3);
    u = hn::Sub(o0, o2);
    v = hn::Sub(o1, o3);
  } else {
    static_assert(T7, "the 2- and 4-row forms take row 7 from its precomputed row pass");
    const auto p0 = hn::OddEven(hn::BitCast(d16, k(32 << 16)), hn::BitCast(d16, x0));
    const V d0 = madd<2048, 2048>(d, p0);  // x0 * 2048 + 65536
    // Row 7's terms, as the R = 8 case adds them (t7 holds them in its high 16 bits).
    const auto p17 = hn::OddEven(hn::BitCast(d16, hn::LoadU(d, t7 + c0)), hn::BitCast(d16, x1));
    const V o0 = madd<kW1, kW7>(d, p17), o1 = madd<kW7, -kW1>(d, p17);
    if constexpr (R > 2) {
      // Rows 2 and 3 as one pair, each multiplied alone (the other factor 0).
      const auto p23 = pairOf(d, x(2), x(3));
      const V e2 = madd<kW2, 0>(d, p23), e3 = madd<kW6, 0>(d, p23);
      const V o2 = madd<0, kW3>(d, p23), o3 = madd<0, -kW5>(d, p23);
      a0 = hn::Add(d0, e2);
      a1 = hn::Add(d0, e3);
      a2 = hn::Sub(d0, e3);
      a3 = hn::Sub(d0, e2);
      b0 = hn::Add(o0, o2);
      b3 = hn::Add(o1, o3);
      u = hn::Sub(o0, o2);
      v = hn::Sub(o1, o3);
    } else {
      // Rows 0 and 1 only: the even part is d0 and the odd sums are o0 and o1 alone.
      a0 = a1 = a2 = a3 = d0;
      b0 = u = o0;
      b3 = v = o1;
    }
  }
  if constexpr (Pcsx2) {
    u = hn::ShiftRight<8>(u);
    v = hn::ShiftRight<8>(v);
    b1 = hn::Mul(hn::Add(u, v), k(181));
    b2 = hn::Mul(hn::Sub(u, v), k(181));
  } else {
    b1 = hn::Mul(hn::ShiftRight<8>(hn::Add(u, v)), k(181));
    b2 = hn::Mul(hn::ShiftRight<8>(hn::Sub(u, v)), k(181));
  }
  out[0] = hn::ShiftRight<17>(hn::Add(a0, b0));
  out[1] = hn::ShiftRight<17>(hn::Add(a1, b1));
  out[2] = hn::ShiftRight<17>(hn::Add(a2, b2));
  out[3] = hn::ShiftRight<17>(hn::Add(a3, b3));
  out[4] = hn::ShiftRight<17>(hn::Sub(a3, b3));
  out[5] = hn::ShiftRight<17>(hn::Sub(a2, b2));
  out[6] = hn::ShiftRight<17>(hn::Sub(a1, b1));
  out[7] = hn::ShiftRight<17>(hn::Sub(a0, b0));
}

#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
// Four output rows of 8 results in 32-bit lanes, added to dst (Add) and stored clamped to 0..255:
// two packssdw, one packuswb and one dword permute for the four rows, where a one-row DemoteTo
// takes three narrowing steps and a mask per row. Exact: a result is an int32 >> 17, so with a
// sample added it is within int16 before the clamp.
template <bool Add>
HWY_INLINE void store4Rows(const hn::Vec256<std::int32_t>* v, std::uint8_t* p, std::ptrdiff_t stride) {
  __m256i r[4];
  for (int y = 0; y < 4; ++y) {
    r[y] = v[y].raw;
    if constexpr (Add) {
      const __m128i px = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + y * stride));
      r[y] = _mm256_add_epi32(r[y], _mm256_cvtepu8_epi32(px));
    }
  }
  // Dwords (4 samples) in the order a0 b0 c0 d0 | a1 b1 c1 d1, then rows a, b | c, d.
  const __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(r[0], r[1]), _mm256_packs_epi32(r[2], r[3]));
  const __m256i rows = _mm256_permutevar8x32_epi32(bytes, _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
  const __m128i ab = _mm256_castsi256_si128(rows);
  const __m128i cd = _mm256_extracti128_si256(rows, 1);
  // The high halves by movhps (a store alone, where a shift down first takes the shuffle port).
  // Not _mm_storeh_pd: GCC 12 writes it as a store through a double*, which UBSan rightly calls
  // misaligned (rows start at any byte); _mm_storeh_pi is a builtin, no typed access.
  _mm_storel_epi64(reinterpret_cast<__m128i*>(p), ab);
  _mm_storeh_pi(reinterpret_cast<__m64*>(p + stride), _mm_castsi128_ps(ab));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 2 * stride), cd);
  _mm_storeh_pi(reinterpret_cast<__m64*>(p + 3 * stride), _mm_castsi128_ps(cd));
}
#endif

#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
// The row pass of two adjacent rows (rows[0..15], one load) together, one per 128-bit block, into
// ra and rb (lane n = output n, 32-bit results whose low 16 bits the column pass takes). A block's
// four lanes hold a0..a3 (even part with the bias) and b0, u + v, u - v, b3 (odd part, from the
// first four lanes of the tables mpeg2Row uses), the 181/256 step on the middle two; outputs 0..3
// are a + b, outputs 4..7 are a - b in reverse lane order. Two rows share each shuffle and multiply
// that mpeg2Row spends on one, and no lane needs the negation of outputs 5 and 6; two block
// permutes at the end put each row's halves together.
template <bool Pcsx2>
HWY_INLINE void mpeg2RowPair(const std::int16_t* rows, hn::Vec256<std::int32_t>& ra, hn::Vec256<std::int32_t>& rb) {
  const hn::Full256<std::int32_t> d;
  const hn::Full256<std::int16_t> d16;
  const hn::Full256<std::uint8_t> d8;
  const auto& T = simd_detail::kMpeg2;
  auto v = hn::LoadU(d16, rows);
  if constexpr (!Pcsx2) v = hn::ShiftLeft<4>(v);  // libmpeg2 0.5.1 holds coefficients x16 (in 16 bits)
  const auto ordered = hn::BitCast(d, hn::TableLookupBytes(hn::BitCast(d8, v), hn::Load(d8, T.pairs2)));
  const auto madd4 = [&](decltype(ordered) pair, const std::int16_t* k) {
    auto s1 = hn::Zero(d);
    const auto s0 = hn::ReorderWidenMulAccumulate(d, hn::BitCast(d16, pair), hn::Load(d16, k), hn::Zero(d), s1);
    return hn::RearrangeToOddPlusEven(s0, s1);
  };
  const auto e =
      hn::Add(hn::Add(madd4(hn::Broadcast<0>(ordered), T.quad[0]), madd4(hn::Broadcast<1>(ordered), T.quad[1])),
              hn::Set(d, Pcsx2 ? 128 : 2048));
  auto o = hn::Add(madd4(hn::Broadcast<2>(ordered), T.quad[2]), madd4(hn::Broadcast<3>(ordered), T.quad[3]));
  const auto k181 = hn::Set(d, 181);
  const auto r = Pcsx2 ? hn::ShiftRight<8>(hn::Mul(o, k181)) : hn::Mul(hn::ShiftRight<8>(o), k181);
  o = hn::Vec256<std::int32_t>{_mm256_blend_epi32(o.raw, r.raw, 0x66)};  // lanes 1 and 2 of each block
  constexpr int kShift = Pcsx2 ? 8 : 12;
  const auto lo = hn::ShiftRight<kShift>(hn::Add(e, o));
  const auto hi = hn::ShiftRight<kShift>(hn::Shuffle0123(hn::Sub(e, o)));
  ra = hn::ConcatLowerLower(d, hi, lo);
  rb = hn::ConcatUpperUpper(d, hi, lo);
}
#endif

// The whole transform; with Add the result is added to dst, else it replaces it (both clamped).
// T7 (R < 8): row 7 goes into the column pass's odd part from its precomputed row pass: that of
// F[7][7] = +-1 alone in row 7 and column 7 (mismatch control) with `toggle`, else zeros.
template <bool Pcsx2, bool Add, int R, bool T7>
HWY_INLINE void mpeg2Rows(const std::int16_t* block, bool toggle, std::uint8_t* dst, int stride) {
  const hn::CappedTag<std::int32_t, 8> d;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const std::size_t N = hn::Lanes(d);
  // Row 7's precomputed pass, [F[7][7] < 0] with the toggle, [2] without, by arithmetic: written as
  // `toggle ? (block[63] < 0) : 2`, GCC 12 made it a branch on the toggle, which follows the parity
  // of the coefficients' sum: a coin toss on most 2- and 4-row residual blocks.
  const unsigned on = toggle ? 1u : 0u;
  const unsigned neg = static_cast<unsigned>(static_cast<std::uint16_t>(block[63]) >> 15);
  const std::int32_t* t7 = simd_detail::kMpeg2.toggleRow[Pcsx2 ? 0 : 1][(neg & on) | ((on ^ 1u) << 1)];
  // Every row through the pass, without a branch on which rows are zero or hold x0 alone (the pass
  // gives 0 and x0 * 8 there): on busy pictures those branches were coin tosses, for the residual
  // blocks of P and B pictures and the 8-row intra blocks alike.
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
  if constexpr (sizeof(hn::Vec<decltype(d)>) == 32) {
    // Two rows per row pass, all 8 columns in one vector per row for the column pass.
    hn::Vec<decltype(d)> x[8], res[8];
    for (int r = 0; r < R; r += 2) mpeg2RowPair<Pcsx2>(block + static_cast<std::ptrdiff_t>(8 * r), x[r], x[r + 1]);
    mpeg2Columns<Pcsx2, R, T7>(d, x, t7, 0, res);
    store4Rows<Add>(res, dst, stride);
    store4Rows<Add>(res + 4, dst + 4 * static_cast<std::ptrdiff_t>(stride), stride);
    return;
  }
#endif
  alignas(64) std::int32_t t[8 * R];
  for (int r = 0; r < R; ++r) {
    mpeg2Row<Pcsx2>(block + static_cast<std::ptrdiff_t>(8 * r), t + static_cast<std::ptrdiff_t>(8 * r));
  }
  for (std::size_t c0 = 0; c0 < 8; c0 += N) {
    hn::Vec<decltype(d)> x[8], res[8];
    for (int r = 0; r < R; ++r) x[r] = hn::LoadU(d, t + static_cast<std::ptrdiff_t>(8 * r) + c0);
    mpeg2Columns<Pcsx2, R, T7>(d, x, t7, c0, res);
    for (int y = 0; y < 8; ++y) {
      std::uint8_t* p = dst + static_cast<std::ptrdiff_t>(y) * stride + c0;
      auto v = res[y];
      if constexpr (Add) v = hn::Add(v, hn::PromoteTo(d, hn::LoadU(d8, p)));
      hn::StoreU(hn::DemoteTo(d8, v), d8, p);
    }
  }
}

template <bool Pcsx2, bool Add>
HWY_INLINE void mpeg2Impl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst,
                          int stride) {
  if (Add && (rowMask & kIdctFirstOnly) && nonIntraDcShortcut(block[0])) {
    // Both decoders' non-intra DC shortcut: a constant residual, F[7][7] ignored. In byte lanes with
    // saturation: the residual is in [-256, 256], and adding +-255 instead of +-256 to a sample in
    // 0..255 clamps to the same end. Both an add and a subtract, one of them by 0: the residual's
    // sign is a coin toss for a branch.
    const hn::FixedTag<std::uint8_t, 8> d8;
    const int v = nonIntraDcResidual(block[0]);
    const auto up = hn::Set(d8, static_cast<std::uint8_t>(std::clamp(v, 0, 255)));
    const auto down = hn::Set(d8, static_cast<std::uint8_t>(std::clamp(-v, 0, 255)));
    for (int y = 0; y < 8; ++y) {
      std::uint8_t* p = dst + static_cast<std::ptrdiff_t>(y) * stride;
      hn::StoreU(hn::SaturatedSub(hn::SaturatedAdd(hn::LoadU(d8, p), up), down), d8, p);
    }
    return;
  }
  // The toggle alone in row 7 is part of both transforms: row 7 goes through the row pass, on its
  // own (T7) unless other rows reach row 4 or beyond. The other rows have nothing in column 7.
  // Blocks of 2 and 4 rows always take the T7 form (a zero row 7 without the toggle): whether the
  // toggle is there follows the parity of the coefficients' sum, a coin toss for a branch.
  const bool toggle = (rowMask & kIdctToggleOnly) != 0;
  // (The column mask does not choose a form: every row goes through the whole row pass.)
  (void)colMask;
  const unsigned rows = rowMask & 0xFF;
  if (rows <= 0x3) return mpeg2Rows<Pcsx2, Add, 2, true>(block, toggle, dst, stride);
  if (rows <= 0xF) return mpeg2Rows<Pcsx2, Add, 4, true>(block, toggle, dst, stride);
  // Eight rows: F[7][7] (with the toggle) is in the block and goes through the row pass with row 7.
  mpeg2Rows<Pcsx2, Add, 8, false>(block, false, dst, stride);
}

void idctPcsx2CopyImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  mpeg2Impl<true, false>(block, rowMask, colMask, dst, stride);
}
void idctPcsx2AddImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  mpeg2Impl<true, true>(block, rowMask, colMask, dst, stride);
}
void idctLibmpeg2CopyImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst,
                          int stride) {
  mpeg2Impl<false, false>(block, rowMask, colMask, dst, stride);
}
void idctLibmpeg2AddImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  mpeg2Impl<false, true>(block, rowMask, colMask, dst, stride);
}
#else
// One-lane fallback target: no 16-bit pairs in a 32-bit lane; the scalar references.
void idctImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  scalarKernels().idctOf(IdctKind::Exact).copy(block, rowMask, colMask, dst, stride);
}
void idctPcsx2CopyImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  scalarKernels().idctOf(IdctKind::Pcsx2).copy(block, rowMask, colMask, dst, stride);
}
void idctPcsx2AddImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  scalarKernels().idctOf(IdctKind::Pcsx2).add(block, rowMask, colMask, dst, stride);
}
void idctLibmpeg2CopyImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst,
                          int stride) {
  scalarKernels().idctOf(IdctKind::Libmpeg2).copy(block, rowMask, colMask, dst, stride);
}
void idctLibmpeg2AddImpl(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  scalarKernels().idctOf(IdctKind::Libmpeg2).add(block, rowMask, colMask, dst, stride);
}
#endif

// The scalar reference's arithmetic for pixels [x0, width) of each line (the tail of the vector loops).
void cscRowsTail(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr, int x0,
                 int width, std::uint8_t* rgba, int rgbaStride, int th0, int th1) {
  for (int x = x0; x < width; ++x) {
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

// Runs block(x) over [0, width) in steps of `step` pixels and returns where the scalar tail starts.
// A last partial step is done by one more block ending at the line's end (overlapping the one
// before it, which gives the same bytes there), started on an even pixel so that its chroma pairs
// stay whole; only an odd line's last pixel is left over.
template <class Block>
int cscSteps(int width, int step, Block&& block) {
  int x = 0;
  for (; x + step <= width; x += step) block(x);
  if (x < width && width >= step + 1) {
    const int last = (width - step) & ~1;
    block(last);
    x = last + step;
  }
  return x;
}

#if HWY_TARGET != HWY_SCALAR && HWY_ARCH_X86 && HWY_TARGET <= HWY_SSSE3
// Saturating narrow of two 16-bit vectors within each 128-bit block (packuswb): Highway 1.0.3 has
// no two-vector i16 -> u8 demote, and its one-vector DemoteTo adds a cross-block permute.
inline hn::Vec128<std::uint8_t> packUs(hn::Vec128<std::int16_t> a, hn::Vec128<std::int16_t> b) {
  return hn::Vec128<std::uint8_t>{_mm_packus_epi16(a.raw, b.raw)};
}
#if HWY_TARGET <= HWY_AVX2
inline hn::Vec256<std::uint8_t> packUs(hn::Vec256<std::int16_t> a, hn::Vec256<std::int16_t> b) {
  return hn::Vec256<std::uint8_t>{_mm256_packus_epi16(a.raw, b.raw)};
}
#endif

// RGB32 without SETTH thresholds (alpha 0x80 everywhere; the saturating narrow is the clamp), 2 x
// 8 or 2 x 16 pixels per step, kept within 128-bit blocks until the store: Y is widened by
// interleaving with zero bytes (block k: pixels 16k..16k+7 in the low vector, 16k+8..16k+15 in the
// high one), which packuswb undoes, so no lane crosses a block before the four RGBA vectors are put
// in memory order. Interleaving zero below Y gives Y << 8, and MulHigh(Y << 8, 0x95 << 2) ==
// (0x95 * Y) >> 6 exactly; the chroma terms (+1 for the rounding) are doubled for the two pixels
// they cover by interleaving them with themselves, which matches the luma layout when block k of
// the term vector holds chroma samples 8k..8k+7 (a plain widening of the 8 or 16 chroma bytes).
int cscRowsOpaqueX86(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                     int width, std::uint8_t* rgba, int rgbaStride) {
  const hn::CappedTag<std::int16_t, 16> d;  // 16 lanes on AVX2 and AVX-512, 8 on SSE4 and SSSE3
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::Repartition<std::uint8_t, decltype(d)> d8;
  const hn::Half<decltype(d8)> dh8;
  constexpr int kBlocks = static_cast<int>(hn::MaxLanes(d8)) / 16;
  static_assert(kBlocks == 1 || kBlocks == 2);
  const int step = static_cast<int>(hn::Lanes(d8));
  const auto kRcr = hn::Set(d, 0xCC << 6), kGcr = hn::Set(d, -0x68 << 6);
  const auto kGcb = hn::Set(d, -0x32 << 6), kBcb = hn::Set(d, 0x102 << 6);
  const auto c128 = hn::Set(d, 128), one = hn::Set(d, 1);
  const auto kY = hn::Set(du, 0x95 << 2);
  const auto zero8 = hn::Zero(d8), y16 = hn::Set(d8, 16), alpha = hn::Set(d8, 0x80);
  return cscSteps(width, step, [&](int x) {
    // (a << 4) * (b << 6) >> 16 == (a * b) >> 6 for these |a| <= 128 (the scalar code's floor shift).
    const auto vb = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(d, hn::LoadU(dh8, cb + x / 2)), c128));
    const auto vr = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(d, hn::LoadU(dh8, cr + x / 2)), c128));
    const auto rT = hn::Add(hn::MulHigh(vr, kRcr), one);
    const auto gT = hn::Add(hn::Add(hn::MulHigh(vr, kGcr), hn::MulHigh(vb, kGcb)), one);
    const auto bT = hn::Add(hn::MulHigh(vb, kBcb), one);
    const auto rLo = hn::InterleaveLower(d, rT, rT), rHi = hn::InterleaveUpper(d, rT, rT);
    const auto gLo = hn::InterleaveLower(d, gT, gT), gHi = hn::InterleaveUpper(d, gT, gT);
    const auto bLo = hn::InterleaveLower(d, bT, bT), bHi = hn::InterleaveUpper(d, bT, bT);
    for (int row = 0; row < rows; ++row) {
      const auto ys = hn::SaturatedSub(hn::LoadU(d8, y + static_cast<std::ptrdiff_t>(row) * yStride + x), y16);
      const auto lumLo = hn::BitCast(d, hn::MulHigh(hn::BitCast(du, hn::InterleaveLower(d8, zero8, ys)), kY));
      const auto lumHi = hn::BitCast(d, hn::MulHigh(hn::BitCast(du, hn::InterleaveUpper(d8, zero8, ys)), kY));
      const auto r = packUs(hn::ShiftRight<1>(hn::Add(lumLo, rLo)), hn::ShiftRight<1>(hn::Add(lumHi, rHi)));
      const auto g = packUs(hn::ShiftRight<1>(hn::Add(lumLo, gLo)), hn::ShiftRight<1>(hn::Add(lumHi, gHi)));
      const auto b = packUs(hn::ShiftRight<1>(hn::Add(lumLo, bLo)), hn::ShiftRight<1>(hn::Add(lumHi, bHi)));
      const auto rgLo = hn::BitCast(du, hn::InterleaveLower(d8, r, g));
      const auto rgHi = hn::BitCast(du, hn::InterleaveUpper(d8, r, g));
      const auto baLo = hn::BitCast(du, hn::InterleaveLower(d8, b, alpha));
      const auto baHi = hn::BitCast(du, hn::InterleaveUpper(d8, b, alpha));
      // Block k of p0..p3: pixels 16k + 0..3, 4..7, 8..11, 12..15.
      const auto p0 = hn::BitCast(d8, hn::InterleaveLower(du, rgLo, baLo));
      const auto p1 = hn::BitCast(d8, hn::InterleaveUpper(du, rgLo, baLo));
      const auto p2 = hn::BitCast(d8, hn::InterleaveLower(du, rgHi, baHi));
      const auto p3 = hn::BitCast(d8, hn::InterleaveUpper(du, rgHi, baHi));
      std::uint8_t* out = rgba + static_cast<std::ptrdiff_t>(row) * rgbaStride + 4 * static_cast<std::ptrdiff_t>(x);
      const int n = step;
      if constexpr (kBlocks == 1) {
        hn::StoreU(p0, d8, out);
        hn::StoreU(p1, d8, out + n);
        hn::StoreU(p2, d8, out + 2 * n);
        hn::StoreU(p3, d8, out + 3 * n);
      } else {
        hn::StoreU(hn::ConcatLowerLower(d8, p1, p0), d8, out);
        hn::StoreU(hn::ConcatLowerLower(d8, p3, p2), d8, out + n);
        hn::StoreU(hn::ConcatUpperUpper(d8, p1, p0), d8, out + 2 * n);
        hn::StoreU(hn::ConcatUpperUpper(d8, p3, p2), d8, out + 3 * n);
      }
    }
  });
}
#endif

// One chroma line's RGB32 rows (1 or 2 luma lines) with the PS2 matrix, in 16-bit lanes:
// lum = (0x95 * max(0, Y - 16)) >> 6, then (lum + term + 1) >> 1 clamped to 0..255; alpha 0x80;
// SETTH. The chroma terms are computed once per chroma sample, at half resolution, and doubled in
// registers for the two pixels (and the two lines) they cover: (a << 4) * (b << 6) >> 16 ==
// (a * b) >> 6 exactly for |a| < 2^11 and the coefficients below (the scalar code's floor shift).
// rc = Cr term of R, gc = both terms of G, bc = Cb term of B. Without thresholds, x86 targets take
// cscRowsOpaqueX86.
void cscRowsImpl(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                 int width, std::uint8_t* rgba, int rgbaStride, int th0, int th1) {
  int x = 0;
#if HWY_TARGET != HWY_SCALAR && HWY_ARCH_X86 && HWY_TARGET <= HWY_SSSE3
  if (th0 <= 0 && th1 <= 0) {
    x = cscRowsOpaqueX86(y, yStride, rows, cb, cr, width, rgba, rgbaStride);
    return cscRowsTail(y, yStride, rows, cb, cr, x, width, rgba, rgbaStride, th0, th1);
  }
#endif
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
  x = cscSteps(width, N, [&](int x0) {
    const auto vb = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(dh, hn::LoadU(dh8, cb + x0 / 2)), c128));
    const auto vr = hn::ShiftLeft<4>(hn::Sub(hn::PromoteTo(dh, hn::LoadU(dh8, cr + x0 / 2)), c128));
    const auto rTerm = doubled(hn::MulHigh(vr, kRcr));
    const auto gTerm = doubled(hn::Add(hn::MulHigh(vr, kGcr), hn::MulHigh(vb, kGcb)));
    const auto bTerm = doubled(hn::MulHigh(vb, kBcb));
    for (int row = 0; row < rows; ++row) {
      const std::uint8_t* yl = y + static_cast<std::ptrdiff_t>(row) * yStride;
      std::uint8_t* out = rgba + static_cast<std::ptrdiff_t>(row) * rgbaStride + 4 * static_cast<std::ptrdiff_t>(x0);
      const auto yy = hn::PromoteTo(d, hn::SaturatedSub(hn::LoadU(d8, yl + x0), hn::Set(d8, 16)));
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
  });
#endif
  cscRowsTail(y, yStride, rows, cb, cr, x, width, rgba, rgbaStride, th0, th1);
}

void cscRowsTarget(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                   int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th) {
  cscRowsImpl(y, yStride, rows, cb, cr, width, rgba, rgbaStride, th.th0, th.th1);
}

// This target's kernels as plain function pointers, picked once: a dispatch per 8x8 block (the
// exported wrappers below) cost about 2 % of a P/B decode. The kernels read only the mask bits
// ipu/kernels.hpp defines.
Kernels kernelTable() {
  return Kernels{{{idctPcsx2CopyImpl, idctPcsx2AddImpl},
                  {idctLibmpeg2CopyImpl, idctLibmpeg2AddImpl},
                  {idctImpl, scalarKernels().idctOf(IdctKind::Exact).add}},
                 cscRowsTarget,
                 nullptr,
                 "highway"};
}

}  // namespace vbim::ipu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "runtime/simd/targets.hpp"

namespace vbim::ipu {

VBIM_SIMD_EXPORT(idctImpl);
VBIM_SIMD_EXPORT(idctPcsx2CopyImpl);
VBIM_SIMD_EXPORT(idctPcsx2AddImpl);
VBIM_SIMD_EXPORT(idctLibmpeg2CopyImpl);
VBIM_SIMD_EXPORT(idctLibmpeg2AddImpl);
VBIM_SIMD_EXPORT(cscRowsImpl);
VBIM_SIMD_EXPORT(kernelTable);

void idctSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  VBIM_SIMD_DISPATCH(idctImpl)(block, rowMask & 0x1FF, colMask & 0xFF, dst, stride);
}

void idctPcsx2Simd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  VBIM_SIMD_DISPATCH(idctPcsx2CopyImpl)(block, rowMask & 0x1FF, colMask & 0xFF, dst, stride);
}
void idctPcsx2AddSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  VBIM_SIMD_DISPATCH(idctPcsx2AddImpl)(block, rowMask & 0x3FF, colMask & 0xFF, dst, stride);
}
void idctLibmpeg2Simd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  VBIM_SIMD_DISPATCH(idctLibmpeg2CopyImpl)(block, rowMask & 0x1FF, colMask & 0xFF, dst, stride);
}
void idctLibmpeg2AddSimd(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride) {
  VBIM_SIMD_DISPATCH(idctLibmpeg2AddImpl)(block, rowMask & 0x3FF, colMask & 0xFF, dst, stride);
}

void cscRowsRgba32Simd(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                       int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th) {
  VBIM_SIMD_DISPATCH(cscRowsImpl)(y, yStride, rows, cb, cr, width, rgba, rgbaStride, th.th0, th.th1);
}

Kernels simdKernelsOfCurrentTarget() {
  Kernels k = VBIM_SIMD_DISPATCH(kernelTable)();
  k.mc = &simdMcKernels();
  return k;
}

const Kernels& simdKernels() {
  // The exact kind's non-intra entry is the scalar one (no P or B picture uses it by default).
  static const Kernels k = simdKernelsOfCurrentTarget();
  return k;
}

const char* simdTargetName() {
  const std::int64_t targets = vbim::simd::supportedTargets() & HWY_TARGETS;
  return hwy::TargetName(targets & -targets);  // the best target has the lowest bit
}

}  // namespace vbim::ipu
#endif
