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

// The row loop of every kernel: `rows` spans of `pixels`, each vector's result given by
// `blend(s, d)`, the last pixels of a span by the scalar reference, the change reduced once at the
// end (a 64x32 tile is one call). kSettle: rows marked in *settled are skipped, blended rows left at
// their fixed point are marked.
template <bool kTrack, bool kSettle, class D8, class BlendVector>
HWY_INLINE int blendRows(D8 d8, std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride,
                         const std::uint8_t* HWY_RESTRICT src, std::size_t srcStride, std::size_t pixels,
                         std::size_t rows, const BlendSpec& spec, std::uint32_t* settled, const BlendVector& blend) {
  const std::size_t bytes = pixels * 4;
  const std::size_t step = hn::Lanes(d8);
  auto deltaAcc = hn::Zero(d8);
  int delta = 0;
  const FixedPointTest<D8> fixed(d8, spec);
  for (std::size_t y = 0; y < rows; ++y, dst += dstStride, src += srcStride) {
    if constexpr (kSettle) {
      if ((*settled >> y) & 1u) continue;
    }
    auto off = hn::Zero(d8);
    std::size_t i = 0;
    for (; i + step <= bytes; i += step) {
      const auto s = hn::LoadU(d8, src + i);
      const auto d = hn::LoadU(d8, dst + i);
      const auto r = blend(s, d);
      if constexpr (kTrack) deltaAcc = hn::Max(deltaAcc, hn::Or(hn::SaturatedSub(r, d), hn::SaturatedSub(d, r)));
      if constexpr (kSettle) off = hn::Or(off, fixed.off(s, r));
      hn::StoreU(r, d8, dst + i);
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
    std::uint8_t lanes[256];  // >= the widest vector of any target
    hn::StoreU(deltaAcc, d8, lanes);
    for (std::size_t k = 0; k < step; ++k) delta = std::max<int>(delta, lanes[k]);
  }
  return delta;
}

// Any FIX, COLCLAMP and alpha mode (the arithmetic in the comment at the top of the file).
template <bool kWide, bool kWrap, bool kKeepAlpha, bool kTrack, bool kSettle>
int blendRectT(std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride, const std::uint8_t* HWY_RESTRICT src,
               std::size_t srcStride, std::size_t pixels, std::size_t rows, const BlendSpec& spec,
               std::uint32_t* settled) {
  const hn::ScalableTag<std::uint8_t> d8;
  const hn::Repartition<std::uint16_t, decltype(d8)> d16;
  const hn::Repartition<std::int16_t, decltype(d8)> di16;
  const hn::Repartition<std::uint32_t, decltype(d8)> d32;
  const auto low = hn::Set(d16, 0x00FF);
  // Even channels (R, B) use FIX. Odd channels are G and A: G uses FIX, A uses 128 (a copy: As is
  // written) or 0 (Ad is kept), so alpha needs no separate select.
  const auto f4 = hn::Set(di16, static_cast<std::int16_t>(spec.fix * 4));
  const std::uint32_t alphaMul = kKeepAlpha ? 0u : 128u * 4u;
  const auto f4odd = hn::BitCast(di16, hn::Set(d32, (alphaMul << 16) | (static_cast<std::uint32_t>(spec.fix) * 4u)));
  const auto zero = hn::Zero(di16);
  const auto max8 = hn::Set(di16, 255);
  const auto blend = [&](hn::Vec<decltype(d8)> s8, hn::Vec<decltype(d8)> d8v) HWY_ATTR {
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
  };
  return blendRows<kTrack, kSettle>(d8, dst, dstStride, src, srcStride, pixels, rows, spec, settled, blend);
}

// FIX = 64, the default smoothing step (half way per vsync), needs no widening:
//     Cd + floor((Cs - Cd) * 64 / 128)  ==  floor((Cs + Cd) / 2)  ==  AverageRound(Cs, Cd) - ((Cs ^ Cd) & 1)
// since AverageRound is (Cs + Cd + 1) >> 1, one more than the floor exactly when Cs + Cd is odd.
// The result lies between Cd and Cs, so COLCLAMP never acts. Alpha is As or Ad, chosen by a byte
// mask. About 8 vector operations per vector against the general kernel's 20, which matters because
// most blends of a play are this one (docs/player.md, "Sixth round").
template <bool kKeepAlpha, bool kTrack, bool kSettle>
int blendHalfRectT(std::uint8_t* HWY_RESTRICT dst, std::size_t dstStride, const std::uint8_t* HWY_RESTRICT src,
                   std::size_t srcStride, std::size_t pixels, std::size_t rows, const BlendSpec& spec,
                   std::uint32_t* settled) {
  const hn::ScalableTag<std::uint8_t> d8;
  const hn::Repartition<std::uint32_t, decltype(d8)> d32;
  const auto one = hn::Set(d8, 1);
  const auto alpha = hn::BitCast(d8, hn::Set(d32, 0xFF000000u));  // byte 3 of each little-endian pixel
  const auto blend = [&](hn::Vec<decltype(d8)> s, hn::Vec<decltype(d8)> d) HWY_ATTR {
    const auto half = hn::Sub(hn::AverageRound(s, d), hn::And(hn::Xor(s, d), one));
    return hn::Or(hn::AndNot(alpha, half), hn::And(alpha, kKeepAlpha ? d : s));
  };
  return blendRows<kTrack, kSettle>(d8, dst, dstStride, src, srcStride, pixels, rows, spec, settled, blend);
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
const char* targetNameHere() {
  return hwy::TargetName(HWY_TARGET);
}

}  // namespace vbim::gs::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "gs/simd/blend_simd.hpp"
#include "gs/simd/compare_simd.hpp"

namespace vbim::gs::simd {

HWY_EXPORT(blendSpan);
HWY_EXPORT(blendSpanDelta);
HWY_EXPORT(blendRectDelta);
HWY_EXPORT(targetNameHere);

namespace {
void dispatchBlend(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  HWY_DYNAMIC_DISPATCH(blendSpan)(dst, src, pixels, spec);
}
int dispatchBlendDelta(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  return HWY_DYNAMIC_DISPATCH(blendSpanDelta)(dst, src, pixels, spec);
}
int dispatchBlendRectDelta(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                           std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
  return HWY_DYNAMIC_DISPATCH(blendRectDelta)(dst, dstStride, src, srcStride, pixels, rows, spec, settled);
}
}  // namespace

const BlendKernels& kernels() {
  // The name is read once; dispatch itself stays dynamic so forEachTarget can force a target.
  static const BlendKernels k{HWY_DYNAMIC_DISPATCH(targetNameHere)(), &dispatchBlend, &dispatchBlendDelta,
                              &dispatchBlendRectDelta, &compareRect};
  return k;
}

void forEachTarget(const std::function<void(const std::string& target)>& fn) {
  (void)kernels();  // name the normal dispatch choice before any target is forced
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    fn(HWY_DYNAMIC_DISPATCH(targetNameHere)());
  }
  hwy::SetSupportedTargetsForTest(0);
}

}  // namespace vbim::gs::simd
#endif  // HWY_ONCE
