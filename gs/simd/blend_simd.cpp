// Highway kernels for the in-place blend. The trick that keeps them fast: no byte shuffles. Each
// 16-bit lane holds two channels; the even channel (R or B) is `lane & 0xFF`, the odd one (G or A)
// is `lane >> 8`, both already widened in place. Per channel, with 9-bit signed differences:
//     ((Cs - Cd) * FIX) >> 7  ==  MulHigh((Cs - Cd) << 7, FIX << 2)
// since (Cs - Cd) << 7 fits in int16 (|.| <= 32640), FIX << 2 <= 1020, and MulHigh keeps the high
// 16 bits of the exact 32-bit product, i.e. floor(product / 65536): the hardware's floor.
// With FIX <= 128 the result lies between Cd and Cs, so COLCLAMP cannot act and is skipped, and
// both channels' steps are added to the lane at once. Alpha rides in the odd channel with a
// multiplier of 128 (As written) or 0 (Ad kept). About 13 vector operations per vector of pixels.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gs/simd/blend_simd.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "gs/blend.hpp"

HWY_BEFORE_NAMESPACE();
namespace vbim::gs::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET == HWY_SCALAR
// One lane cannot be split into two 16-bit halves: the scalar target is the reference itself.
template <bool kWide, bool kWrap, bool kKeepAlpha, bool kTrack, bool kSettle>
int blendRectT(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
               std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
  if constexpr (kTrack) return blendRectDeltaScalar(dst, dstStride, src, srcStride, pixels, rows, spec, settled);
  for (std::size_t y = 0; y < rows; ++y) blendSpanScalar(dst + y * dstStride, src + y * srcStride, pixels, spec);
  return 0;
}
#else
// The fixed-point test of spanAtFixedPoint (gs/blend.hpp) on a vector: non-zero bytes where a
// further blend would move the result r. Per byte, r is fixed when Cs - r <= band and r <= Cs (the
// latter not needed for FIX 0, which moves nothing). Alpha: r == As when As is written; nothing when
// Ad is kept. Four vector operations.
template <class D8>
struct FixedPointTest {
  hn::Vec<D8> band, underMask;
  FixedPointTest(D8 d8, const BlendSpec& spec) {
    const hn::Repartition<std::uint32_t, D8> d32;
    const bool keepAlpha = spec.alpha == AlphaWrite::Keep;
    const auto colourBand = static_cast<std::uint32_t>(fixedPointBand(spec.fix));
    band = hn::BitCast(d8, hn::Set(d32, (keepAlpha ? 0xFF000000u : 0u) | colourBand * 0x010101u));
    underMask = hn::BitCast(d8, hn::Set(d32, (keepAlpha ? 0u : 0xFF000000u) | (spec.fix == 0 ? 0u : 0x00FFFFFFu)));
  }
  hn::Vec<D8> off(hn::Vec<D8> s, hn::Vec<D8> r) const {
    return hn::Or(hn::And(hn::SaturatedSub(r, s), underMask), hn::SaturatedSub(hn::SaturatedSub(s, r), band));
  }
};

// The change and the fixed-point test of the FIX 64 blend (HalfBlend) from the byte distances to
// the target alone, a = Cs -sat Cd and b = Cd -sat Cs, kept as their maxima: two subtractions and
// two maxima a vector where the general tests (FixedPointTest, |r - Cd|) take nine. Exact, for the
// blend r = floor((Cs + Cd) / 2) of a colour byte:
//   its change |r - Cd| is floor(a / 2) (Cs >= Cd) or ceil(b / 2) (Cd > Cs), the other distance
//   being 0; both grow with the distance, so the largest change is max(floor(A / 2), ceil(B / 2))
//   of the maxima A and B;
//   r is at its fixed point (spanAtFixedPoint: 0 <= Cs - r <= fixedPointBand(64) = 1) unless
//   Cs - r = ceil((Cs - Cd) / 2) is 2 or more (a >= 3) or below 0 (b >= 2).
// Alpha is As (AlphaWrite::Source: change |As - Ad| = max(a, b), then at its fixed point) or Ad
// (Keep: no change). The tests compare every (Cs, Cd) pair with the scalar reference.
template <class D8, bool kKeepAlpha>
struct HalfChange {
  hn::Vec<D8> colour, two, one;
  explicit HalfChange(D8 d8) {
    const hn::Repartition<std::uint32_t, D8> d32;
    colour = hn::BitCast(d8, hn::Set(d32, 0x00FFFFFFu));  // bytes 0-2 of each little-endian pixel
    two = hn::Set(d8, 2);
    one = hn::Set(d8, 1);
  }
  // Non-zero bytes where a blended row whose distances had maxima rowA, rowB is not at its fixed point.
  hn::Vec<D8> off(hn::Vec<D8> rowA, hn::Vec<D8> rowB) const {
    return hn::And(hn::Or(hn::SaturatedSub(rowA, two), hn::SaturatedSub(rowB, one)), colour);
  }
  // The largest change of each byte lane, from the maxima of its distances.
  hn::Vec<D8> change(D8 d8, hn::Vec<D8> a, hn::Vec<D8> b) const {
    const auto zero = hn::Zero(d8);
    const auto colourChange = hn::Max(hn::Sub(a, hn::AverageRound(a, zero)), hn::AverageRound(b, zero));
    const auto alphaChange = kKeepAlpha ? zero : hn::Max(a, b);
    return hn::Or(hn::And(colour, colourChange), hn::AndNot(colour, alphaChange));
  }
};

// FIX 64's pass over one row of a tile or span: blends s into d whole vectors at a time from byte i
// on, and keeps in rowA / rowB the largest s - d and d - s per byte lane (HalfChange turns them
// into the change and the settled mark). Leaves i at the first byte of the scalar tail.
template <class D8, class Blend, class V>
HWY_INLINE void halfTrackRow(D8 d8, const Blend& blendIn, const std::uint8_t* HWY_RESTRICT s,
                             std::uint8_t* HWY_RESTRICT d, std::size_t bytes, std::size_t& i, V& rowA, V& rowB) {
  // A local copy: the stores through d (bytes, which may alias anything) would otherwise make the
  // compiler reload the blend's constant vectors from *blendIn at every step.
  const Blend blend = blendIn;
  const std::size_t step = hn::Lanes(d8);
  for (; i + step <= bytes; i += step) {
    const auto sv = hn::LoadU(d8, s + i);
    const auto dv = hn::LoadU(d8, d + i);
    rowA = hn::Max(rowA, hn::SaturatedSub(sv, dv));
    rowB = hn::Max(rowB, hn::SaturatedSub(dv, sv));
    hn::StoreU(blend(sv, dv), d8, d + i);
  }
}

// The row loop of every kernel: `rows` spans of `pixels`, each vector's result given by
// `blend(s, d)`, the last pixels of a span by the scalar reference, the change reduced once at the
// end (a 64x32 tile is one call). kSettle: rows marked in *settled are skipped, blended rows left at
// their fixed point are marked.
template <bool kTrack, bool kSettle, class D8, class BlendVector>
HWY_INLINE int blendRows(D8 d8, std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride,
                         const std::uint8_t* HWY_RESTRICT src, std::size_t srcStride, std::size_t pixels,
                         std::size_t rows, const BlendSpec& spec, std::uint32_t* settled, const BlendVector& blendIn) {
  const BlendVector blend = blendIn;  // in registers: see halfTrackRow
  const std::size_t bytes = pixels * 4;
  const std::size_t step = hn::Lanes(d8);
  auto deltaAcc = hn::Zero(d8);
  int delta = 0;
  const FixedPointTest<D8> fixed(d8, spec);
  // FIX 64 with the change wanted: the distances' maxima instead (HalfChange).
  constexpr bool kHalfTrack = kTrack && BlendVector::kHalf;
  const HalfChange<D8, BlendVector::kKeep> half(d8);
  auto accA = hn::Zero(d8), accB = hn::Zero(d8);
  for (std::size_t y = 0; y < rows; ++y, dst += dstStride, src += srcStride) {
    if constexpr (kSettle) {
      if ((*settled >> y) & 1u) continue;
    }
    auto off = hn::Zero(d8);
    std::size_t i = 0;
    if constexpr (kHalfTrack) {
      auto rowA = hn::Zero(d8), rowB = hn::Zero(d8);
      halfTrackRow(d8, blend, src, dst, bytes, i, rowA, rowB);
      accA = hn::Max(accA, rowA);
      accB = hn::Max(accB, rowB);
      if constexpr (kSettle) off = half.off(rowA, rowB);
    } else {
      for (; i + step <= bytes; i += step) {
        const auto s = hn::LoadU(d8, src + i);
        const auto d = hn::LoadU(d8, dst + i);
        const auto r = blend(s, d);
        if constexpr (kTrack) deltaAcc = hn::Max(deltaAcc, hn::Or(hn::SaturatedSub(r, d), hn::SaturatedSub(d, r)));
        if constexpr (kSettle) off = hn::Or(off, fixed.off(s, r));
        hn::StoreU(r, d8, dst + i);
      }
    }
    bool tailFixed = true;
    if (i < bytes) {
      const std::size_t rest = (bytes - i) / 4;
      delta = std::max(delta, blendSpanDeltaScalar(dst + i, src + i, rest, spec));
      if constexpr (kSettle) tailFixed = spanAtFixedPoint(dst + i, src + i, rest, spec);
    }
    if constexpr (kSettle) {
      if (tailFixed && hn::AllTrue(d8, hn::Eq(off, hn::Zero(d8)))) *settled |= 1u << y;
    }
  }
  if constexpr (kTrack) {
    if constexpr (kHalfTrack) deltaAcc = half.change(d8, accA, accB);
    std::uint8_t lanes[256];  // >= the widest vector of any target
    hn::StoreU(deltaAcc, d8, lanes);
    for (std::size_t k = 0; k < step; ++k) delta = std::max<int>(delta, lanes[k]);
  }
  return delta;
}

// Any FIX, COLCLAMP and alpha mode (the arithmetic in the comment at the top of the file).
template <bool kWide, bool kWrap, bool kKeepAlpha>
struct GeneralBlend {
  static constexpr bool kHalf = false;
  static constexpr bool kKeep = kKeepAlpha;
  using D8 = hn::ScalableTag<std::uint8_t>;
  using D16 = hn::Repartition<std::uint16_t, D8>;
  using DI16 = hn::Repartition<std::int16_t, D8>;
  using D32 = hn::Repartition<std::uint32_t, D8>;
  hn::Vec<D16> low;
  hn::Vec<DI16> f4, f4odd, zero, max8;
  explicit GeneralBlend(const BlendSpec& spec) {
    const D16 d16;
    const DI16 di16;
    const D32 d32;
    low = hn::Set(d16, 0x00FF);
    // Even channels (R, B) use FIX. Odd channels are G and A: G uses FIX, A uses 128 (a copy: As is
    // written) or 0 (Ad is kept), so alpha needs no separate select.
    f4 = hn::Set(di16, static_cast<std::int16_t>(spec.fix * 4));
    const std::uint32_t alphaMul = kKeepAlpha ? 0u : 128u * 4u;
    f4odd = hn::BitCast(di16, hn::Set(d32, (alphaMul << 16) | (static_cast<std::uint32_t>(spec.fix) * 4u)));
    zero = hn::Zero(di16);
    max8 = hn::Set(di16, 255);
  }
  HWY_INLINE hn::Vec<D8> operator()(hn::Vec<D8> s8, hn::Vec<D8> d8v) const {
    const D8 d8;
    const D16 d16;
    const DI16 di16;
    const auto s = hn::BitCast(d16, s8);
    const auto d = hn::BitCast(d16, d8v);
    const auto se = hn::BitCast(di16, hn::And(s, low));
    const auto de = hn::BitCast(di16, hn::And(d, low));
    const auto so = hn::BitCast(di16, hn::ShiftRight<8>(s));
    const auto dod = hn::BitCast(di16, hn::ShiftRight<8>(d));
    const auto me = hn::MulHigh(hn::ShiftLeft<7>(hn::Sub(se, de)), f4);
    const auto mo = hn::MulHigh(hn::ShiftLeft<7>(hn::Sub(so, dod)), f4odd);
    if constexpr (!kWide) {
      // FIX <= 128: each channel's result stays in 0..255, so the two steps add to the 16-bit lane
      // without carries: Cd + me + (mo << 8).
      return hn::BitCast(d8, hn::Add(hn::Add(d, hn::BitCast(d16, me)), hn::ShiftLeft<8>(hn::BitCast(d16, mo))));
    } else {
      auto te = hn::Add(me, de);
      auto to = hn::Add(mo, dod);
      if constexpr (kWrap) {
        te = hn::BitCast(di16, hn::And(hn::BitCast(d16, te), low));  // odd lane: << 8 drops the rest
      } else {
        te = hn::Min(hn::Max(te, zero), max8);
        to = hn::Min(hn::Max(to, zero), max8);
      }
      return hn::BitCast(d8, hn::Or(hn::BitCast(d16, te), hn::ShiftLeft<8>(hn::BitCast(d16, to))));
    }
  }
};

template <bool kWide, bool kWrap, bool kKeepAlpha, bool kTrack, bool kSettle>
int blendRectT(std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride, const std::uint8_t* HWY_RESTRICT src,
               std::size_t srcStride, std::size_t pixels, std::size_t rows, const BlendSpec& spec,
               std::uint32_t* settled) {
  const hn::ScalableTag<std::uint8_t> d8;
  return blendRows<kTrack, kSettle>(d8, dst, dstStride, src, srcStride, pixels, rows, spec, settled,
                                    GeneralBlend<kWide, kWrap, kKeepAlpha>(spec));
}

// FIX = 64, the default smoothing step (half way per vsync), needs no widening:
//     Cd + floor((Cs - Cd) * 64 / 128)  ==  floor((Cs + Cd) / 2)  ==  AverageRound(Cs, Cd) - ((Cs ^ Cd) & 1)
// since AverageRound is (Cs + Cd + 1) >> 1, one more than the floor exactly when Cs + Cd is odd.
// The result lies between Cd and Cs, so COLCLAMP never acts. Alpha is As or Ad, chosen by a byte
// mask. About 8 vector operations per vector against the general kernel's 20, which matters because
// most blends of a play are this one (docs/player.md, "Sixth round").
template <bool kKeepAlpha>
struct HalfBlend {
  static constexpr bool kHalf = true;
  static constexpr bool kKeep = kKeepAlpha;
  using D8 = hn::ScalableTag<std::uint8_t>;
  hn::Vec<D8> one, alpha;
  HalfBlend() {
    const D8 d8;
    const hn::Repartition<std::uint32_t, D8> d32;
    one = hn::Set(d8, 1);
    alpha = hn::BitCast(d8, hn::Set(d32, 0xFF000000u));  // byte 3 of each little-endian pixel
  }
  HWY_INLINE hn::Vec<D8> operator()(hn::Vec<D8> s, hn::Vec<D8> d) const {
    const auto half = hn::Sub(hn::AverageRound(s, d), hn::And(hn::Xor(s, d), one));
    return hn::Or(hn::AndNot(alpha, half), hn::And(alpha, kKeepAlpha ? d : s));
  }
};

template <bool kKeepAlpha, bool kTrack, bool kSettle>
int blendHalfRectT(std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride, const std::uint8_t* HWY_RESTRICT src,
                   std::size_t srcStride, std::size_t pixels, std::size_t rows, const BlendSpec& spec,
                   std::uint32_t* settled) {
  const hn::ScalableTag<std::uint8_t> d8;
  return blendRows<kTrack, kSettle>(d8, dst, dstStride, src, srcStride, pixels, rows, spec, settled,
                                    HalfBlend<kKeepAlpha>());
}

// The words of one image row folded into the hash chain with its lanes in registers, rotated so
// that r0 is the lane of the row's first word: then each 32-byte block is r0..r3 whatever the row's
// phase, and the blend of the next tile overlaps the multiply chains (which the CPU would otherwise
// wait on: they are latency-bound, the blend throughput-bound).
struct RowHash {
  std::uint64_t r0, r1, r2, r3;
  unsigned phase;
  explicit RowHash(const HashChain& c) : phase(static_cast<unsigned>(c.count & 3)) {
    r0 = c.lanes[phase];
    r1 = c.lanes[(phase + 1) & 3];
    r2 = c.lanes[(phase + 2) & 3];
    r3 = c.lanes[(phase + 3) & 3];
  }
  // n bytes, a multiple of 32 (every tile but a row's last).
  HWY_INLINE void blocks(const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 32) {
      r0 = (r0 ^ HashChain::loadLe(p + i)) * HashChain::kPrime;
      r1 = (r1 ^ HashChain::loadLe(p + i + 8)) * HashChain::kPrime;
      r2 = (r2 ^ HashChain::loadLe(p + i + 16)) * HashChain::kPrime;
      r3 = (r3 ^ HashChain::loadLe(p + i + 24)) * HashChain::kPrime;
    }
  }
  // The row's last bytes (a whole number of words), then the lanes back into the chain, which has
  // then taken rowWords words.
  HWY_INLINE void finish(const std::uint8_t* p, std::size_t n, std::size_t rowWords, HashChain& c) {
    const std::size_t whole = n / 32 * 32;
    blocks(p, whole);
    // At most three words are left (n - whole < 32): r0, r1, r2 in turn.
    const std::size_t left = (n - whole) / 8;
    if (left > 0) r0 = (r0 ^ HashChain::loadLe(p + whole)) * HashChain::kPrime;
    if (left > 1) r1 = (r1 ^ HashChain::loadLe(p + whole + 8)) * HashChain::kPrime;
    if (left > 2) r2 = (r2 ^ HashChain::loadLe(p + whole + 16)) * HashChain::kPrime;
    c.lanes[phase] = r0;
    c.lanes[(phase + 1) & 3] = r1;
    c.lanes[(phase + 2) & 3] = r2;
    c.lanes[(phase + 3) & 3] = r3;
    c.count += rowWords;
  }
};

// BlendHashRowsFn (gs/blend.hpp): row by row, each tile's part of the row blended (skipped where its
// settled bit is set) and folded into the chain right after, while it is in L1. Each tile's change
// is kept as a vector (a byte maximum) and reduced once per call.
template <class Blend>
void blendHashRowsImpl(std::uint8_t* HWY_RESTRICT dst, const std::uint8_t* HWY_RESTRICT src, std::size_t pixels,
                       std::size_t rows, std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled,
                       int* delta, HashChain* chain, const Blend& blendIn) {
  const Blend blend = blendIn;  // in registers: see halfTrackRow
  using D8 = hn::ScalableTag<std::uint8_t>;
  const D8 d8;
  const std::size_t step = hn::Lanes(d8);
  const std::size_t tiles = (pixels + tilePixels - 1) / tilePixels;
  constexpr std::size_t kMaxTiles = 64;
  constexpr std::size_t kMaxLanes = 64;
  // Rows fold in registers when they are whole words and every tile but the last whole blocks.
  const bool rowWise = chain != nullptr && pixels % 2 == 0 && tilePixels % 8 == 0;
  if (tiles > kMaxTiles || step > kMaxLanes) {
    blendHashRowsScalar(dst, src, pixels, rows, tilePixels, spec, settled, delta, chain);
    return;
  }
  // Per tile, its bytes' largest change; for FIX 64 the largest distances Cs - Cd (acc) and Cd - Cs
  // (accB) instead, turned into the change at the end (HalfChange).
  HWY_ALIGN std::uint8_t acc[kMaxTiles * kMaxLanes];
  HWY_ALIGN std::uint8_t accB[Blend::kHalf ? kMaxTiles * kMaxLanes : 1];
  for (std::size_t t = 0; t < tiles; ++t) hn::Store(hn::Zero(d8), d8, acc + t * step);
  if constexpr (Blend::kHalf) {
    for (std::size_t t = 0; t < tiles; ++t) hn::Store(hn::Zero(d8), d8, accB + t * step);
  }
  const FixedPointTest<D8> fixed(d8, spec);
  const HalfChange<D8, Blend::kKeep> half(d8);
  const std::size_t stride = pixels * 4;
  for (std::size_t y = 0; y < rows; ++y) {
    std::uint8_t* drow = dst + y * stride;
    const std::uint8_t* srow = src + y * stride;
    RowHash h(rowWise ? *chain : HashChain{});
    for (std::size_t t = 0, x0 = 0; t < tiles; ++t, x0 += tilePixels) {
      const std::size_t bytes = std::min(tilePixels, pixels - x0) * 4;
      std::uint8_t* d = drow + 4 * x0;
      const std::uint8_t* s = srow + 4 * x0;
      if (((settled[t] >> y) & 1u) == 0) {
        auto off = hn::Zero(d8);
        std::size_t i = 0;
        if constexpr (Blend::kHalf) {
          auto rowA = hn::Zero(d8), rowB = hn::Zero(d8);
          halfTrackRow(d8, blend, s, d, bytes, i, rowA, rowB);
          hn::Store(hn::Max(hn::Load(d8, acc + t * step), rowA), d8, acc + t * step);
          hn::Store(hn::Max(hn::Load(d8, accB + t * step), rowB), d8, accB + t * step);
          off = half.off(rowA, rowB);
        } else {
          auto change = hn::Load(d8, acc + t * step);
          for (; i + step <= bytes; i += step) {
            const auto sv = hn::LoadU(d8, s + i);
            const auto dv = hn::LoadU(d8, d + i);
            const auto r = blend(sv, dv);
            change = hn::Max(change, hn::Or(hn::SaturatedSub(r, dv), hn::SaturatedSub(dv, r)));
            off = hn::Or(off, fixed.off(sv, r));
            hn::StoreU(r, d8, d + i);
          }
          hn::Store(change, d8, acc + t * step);
        }
        bool tailFixed = true;
        if (i < bytes) {
          const std::size_t rest = (bytes - i) / 4;
          delta[t] = std::max(delta[t], blendSpanDeltaScalar(d + i, s + i, rest, spec));
          tailFixed = spanAtFixedPoint(d + i, s + i, rest, spec);
        }
        if (tailFixed && hn::AllTrue(d8, hn::Eq(off, hn::Zero(d8)))) settled[t] |= 1u << y;
      }
      if (rowWise) {
        if (t + 1 < tiles) {
          h.blocks(d, bytes);
        } else {
          h.finish(d, bytes, stride / 8, *chain);
        }
      }
    }
  }
  for (std::size_t t = 0; t < tiles; ++t) {
    if constexpr (Blend::kHalf) {
      hn::Store(half.change(d8, hn::Load(d8, acc + t * step), hn::Load(d8, accB + t * step)), d8, acc + t * step);
    }
    for (std::size_t k = 0; k < step; ++k) delta[t] = std::max<int>(delta[t], acc[t * step + k]);
  }
  if (chain != nullptr && !rowWise) chain->addBytes(dst, stride * rows);
}
#endif

template <bool kTrack, bool kSettle>
int dispatchT(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
              std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
  const bool wide = spec.fix > 128;
  const bool wrap = spec.colclamp == ColClamp::Wrap;
  const bool keep = spec.alpha == AlphaWrite::Keep;
#if HWY_TARGET != HWY_SCALAR
  if (spec.fix == 64) {
    return keep ? blendHalfRectT<true, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec, settled)
                : blendHalfRectT<false, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec, settled);
  }
#endif
  if (!wide) {
    return keep ? blendRectT<false, false, true, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                                  settled)
                : blendRectT<false, false, false, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                                   settled);
  }
  if (wrap) {
    return keep ? blendRectT<true, true, true, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                                settled)
                : blendRectT<true, true, false, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                                 settled);
  }
  return keep ? blendRectT<true, false, true, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                               settled)
              : blendRectT<true, false, false, kTrack, kSettle>(dst, dstStride, src, srcStride, pixels, rows, spec,
                                                                settled);
}

void blendSpan(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  dispatchT<false, false>(dst, 0, src, 0, pixels, 1, spec, nullptr);
}
int blendSpanDelta(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  return dispatchT<true, false>(dst, 0, src, 0, pixels, 1, spec, nullptr);
}
int blendRectDelta(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                   std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
  return settled != nullptr ? dispatchT<true, true>(dst, dstStride, src, srcStride, pixels, rows, spec, settled)
                            : dispatchT<true, false>(dst, dstStride, src, srcStride, pixels, rows, spec, nullptr);
}
void blendHashRows(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, std::size_t rows,
                   std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled, int* delta,
                   HashChain* chain) {
#if HWY_TARGET == HWY_SCALAR
  blendHashRowsScalar(dst, src, pixels, rows, tilePixels, spec, settled, delta, chain);
#else
  const bool keep = spec.alpha == AlphaWrite::Keep;
  const auto run = [&](const auto& blend) {
    blendHashRowsImpl(dst, src, pixels, rows, tilePixels, spec, settled, delta, chain, blend);
  };
  if (spec.fix == 64) {
    return keep ? run(HalfBlend<true>()) : run(HalfBlend<false>());
  }
  if (spec.fix <= 128) {
    return keep ? run(GeneralBlend<false, false, true>(spec)) : run(GeneralBlend<false, false, false>(spec));
  }
  if (spec.colclamp == ColClamp::Wrap) {
    return keep ? run(GeneralBlend<true, true, true>(spec)) : run(GeneralBlend<true, true, false>(spec));
  }
  return keep ? run(GeneralBlend<true, false, true>(spec)) : run(GeneralBlend<true, false, false>(spec));
#endif
}

const char* targetNameHere() {
  return hwy::TargetName(HWY_TARGET);
}

}  // namespace vbim::gs::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <atomic>

#include "gs/simd/blend_simd.hpp"
#include "gs/simd/compare_simd.hpp"
#include "runtime/simd/targets.hpp"

namespace vbim::gs::simd {

VBIM_SIMD_EXPORT(blendSpan);
VBIM_SIMD_EXPORT(blendSpanDelta);
VBIM_SIMD_EXPORT(blendRectDelta);
VBIM_SIMD_EXPORT(blendHashRows);
VBIM_SIMD_EXPORT(targetNameHere);

namespace {

// AVX-512 gives way to AVX2 for these kernels on a CPU that has both, except while forEachTarget
// forces each target in turn (the tests check every one). The
// kernels alone are about as fast either way (bench_blend_hash: the fused pass within 5 %), but the
// 512x512 play ran 1.14-1.21x faster in CPU time with them on AVX2 (Intel Xeon Ice Lake-SP, 2 vCPU,
// 2026-12-05, bench/player/play_speed_ab.sh; docs/player.md "Speed and memory"): 512-bit
// instructions lower the core's clock for a while after they run and close port 1's vector unit,
// which costs the code between the blends (decode, scheduler) more than the wider vectors save. [A]
// that other AVX-512 CPUs behave alike; the bytes are the same on every target.
// Asked once: CPUID is slow in a virtual machine (asked per call, it was 44 % of a play).
bool avx2PreferredOnThisCpu() {
#if HWY_TARGETS & HWY_AVX2
  const std::int64_t supported = vbim::simd::supportedTargets();
  return (supported & HWY_AVX2) != 0 && (supported & (HWY_AVX3 | HWY_AVX3_DL)) != 0;
#else
  return false;
#endif
}
std::atomic<bool> targetForced{false};  // forEachTarget is running: the forced target decides
bool avx2Preferred() {
  static const bool onThisCpu = avx2PreferredOnThisCpu();
  return onThisCpu && !targetForced.load(std::memory_order_relaxed);
}

void dispatchBlend(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
#if HWY_TARGETS & HWY_AVX2
  if (avx2Preferred()) {
    N_AVX2::blendSpan(dst, src, pixels, spec);
    return;
  }
#endif
  VBIM_SIMD_DISPATCH(blendSpan)(dst, src, pixels, spec);
}
int dispatchBlendDelta(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
#if HWY_TARGETS & HWY_AVX2
  if (avx2Preferred()) return N_AVX2::blendSpanDelta(dst, src, pixels, spec);
#endif
  return VBIM_SIMD_DISPATCH(blendSpanDelta)(dst, src, pixels, spec);
}
int dispatchBlendRectDelta(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                           std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
#if HWY_TARGETS & HWY_AVX2
  if (avx2Preferred()) return N_AVX2::blendRectDelta(dst, dstStride, src, srcStride, pixels, rows, spec, settled);
#endif
  return VBIM_SIMD_DISPATCH(blendRectDelta)(dst, dstStride, src, srcStride, pixels, rows, spec, settled);
}
void dispatchBlendHashRows(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, std::size_t rows,
                           std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled, int* delta,
                           HashChain* chain) {
#if HWY_TARGETS & HWY_AVX2
  if (avx2Preferred()) {
    N_AVX2::blendHashRows(dst, src, pixels, rows, tilePixels, spec, settled, delta, chain);
    return;
  }
#endif
  VBIM_SIMD_DISPATCH(blendHashRows)(dst, src, pixels, rows, tilePixels, spec, settled, delta, chain);
}
const char* targetName() {
  return avx2Preferred() ? hwy::TargetName(HWY_AVX2) : VBIM_SIMD_DISPATCH(targetNameHere)();
}
}  // namespace

const BlendKernels& kernels() {
  // The name is read once; dispatch itself stays dynamic so forEachTarget can force a target.
  static const BlendKernels k{targetName(), &dispatchBlend,        &dispatchBlendDelta, &dispatchBlendRectDelta,
                              &compareRect, &dispatchBlendHashRows};
  return k;
}

void forEachTarget(const std::function<void(const std::string& target)>& fn) {
  (void)kernels();  // name the normal dispatch choice before any target is forced
  targetForced = true;
  struct Release {
    ~Release() { targetForced = false; }
  } release;
  vbim::simd::forEachTarget(HWY_TARGETS, [&](std::int64_t) { fn(targetName()); });
}

}  // namespace vbim::gs::simd
#endif  // HWY_ONCE
