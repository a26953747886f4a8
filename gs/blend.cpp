#include "gs/blend.hpp"

#include <cstdlib>
#include <string>

#include "gs/error.hpp"

namespace vbim::gs {

BlendSpec makeBlendSpec(std::int64_t fix, ColClamp colclamp, AlphaWrite alpha) {
  if (fix < 0 || fix > 255) {
    throw GsError("blend FIX " + std::to_string(fix) +
                  " is outside 0..255 (ALPHA.FIX is an 8-bit field; 128 = 1.0, 64 = half way per vsync)");
  }
  return BlendSpec{static_cast<std::uint8_t>(fix), colclamp, alpha};
}

namespace {

template <bool kTrack>
int blendSpan(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  const int fix = spec.fix;
  const ColClamp cc = spec.colclamp;
  const bool keepAlpha = spec.alpha == AlphaWrite::Keep;
  int delta = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* d = dst + 4 * i;
    const std::uint8_t* s = src + 4 * i;
    for (int c = 0; c < 3; ++c) {
      const int v = blendChannel(s[c], d[c], fix, cc);
      if constexpr (kTrack) delta = std::max(delta, std::abs(v - d[c]));
      d[c] = static_cast<std::uint8_t>(v);
    }
    if (!keepAlpha) {
      if constexpr (kTrack) delta = std::max(delta, std::abs(s[3] - d[3]));
      d[3] = s[3];
    }
  }
  return delta;
}

}  // namespace

void blendSpanScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  blendSpan<false>(dst, src, pixels, spec);
}

int blendSpanDeltaScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  return blendSpan<true>(dst, src, pixels, spec);
}

int blendRectDeltaScalar(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                         std::size_t pixels, std::size_t rows, const BlendSpec& spec, std::uint32_t* settled) {
  int delta = 0;
  for (std::size_t y = 0; y < rows; ++y, dst += dstStride, src += srcStride) {
    if (settled != nullptr && (*settled >> y) & 1u) continue;
    delta = std::max(delta, blendSpan<true>(dst, src, pixels, spec));
    if (settled != nullptr && spanAtFixedPoint(dst, src, pixels, spec)) *settled |= 1u << y;
  }
  return delta;
}

void blendHashRowsScalar(std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, std::size_t rows,
                         std::size_t tilePixels, const BlendSpec& spec, std::uint32_t* settled, int* delta,
                         HashChain* chain) {
  const std::size_t stride = pixels * 4;
  for (std::size_t x0 = 0, t = 0; x0 < pixels; x0 += tilePixels, ++t) {
    const std::size_t w = std::min(tilePixels, pixels - x0);
    delta[t] = std::max(delta[t],
                        blendRectDeltaScalar(dst + 4 * x0, stride, src + 4 * x0, stride, w, rows, spec, settled + t));
  }
  if (chain != nullptr) chain->addBytes(dst, stride * rows);
}

bool spanAtFixedPoint(const std::uint8_t* dst, const std::uint8_t* src, std::size_t pixels, const BlendSpec& spec) {
  const bool keepAlpha = spec.alpha == AlphaWrite::Keep;
  for (std::size_t i = 0; i < 4 * pixels; i += 4) {
    for (int c = 0; c < 3; ++c)
      if (!isFixedPoint(src[i + c], dst[i + c], spec.fix)) return false;
    if (!keepAlpha && src[i + 3] != dst[i + 3]) return false;
  }
  return true;
}

const BlendKernels& scalarKernels() {
  static const BlendKernels k{"scalar",           &blendSpanScalar,    &blendSpanDeltaScalar, &blendRectDeltaScalar,
                              &compareRectScalar, &blendHashRowsScalar};
  return k;
}

}  // namespace vbim::gs
