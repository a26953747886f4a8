#include "gs/blend16.hpp"

#include <cstdlib>

namespace vbim::gs {

std::uint64_t dimxRegister() {
  std::uint64_t v = 0;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      v |= static_cast<std::uint64_t>(kDimx[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] & 0x7)
           << (16 * y + 4 * x);
    }
  }
  return v;
}

void staging16FromRgb32(const Rgba8Image& frame, Rgba8Image& out) {
  if (!out.sameSize(frame)) out = Rgba8Image(frame.width, frame.height);
  for (int y = 0; y < frame.height; ++y) {
    const std::uint8_t* s = frame.row(y);
    std::uint8_t* d = out.row(y);
    const auto& dither = kIpuDither[static_cast<std::size_t>(y & 3)];
    for (int x = 0; x < frame.width; ++x, s += 4, d += 4) {
      for (int c = 0; c < 3; ++c) {
        d[c] = static_cast<std::uint8_t>(std::clamp(s[c] + dither[static_cast<std::size_t>(x & 3)], 0, 255) & 0xF8);
      }
      // RGB16 bit 15 is set where the RGB32 alpha was 0x40; TEXA turns it into TA1, else TA0.
      d[3] = s[3] == 0x40 ? 0x40 : 0x80;
    }
  }
}

int blend16Rect(std::uint8_t* dst, std::size_t dstStride, const std::uint8_t* src, std::size_t srcStride,
                std::size_t pixels, std::size_t rows, int x0, int y0, const BlendSpec& spec) {
  const bool keepAlpha = spec.alpha == AlphaWrite::Keep;
  int delta = 0;
  for (std::size_t r = 0; r < rows; ++r, dst += dstStride, src += srcStride) {
    const auto& dimx = kDimx[static_cast<std::size_t>((y0 + static_cast<int>(r)) & 3)];
    for (std::size_t i = 0; i < pixels; ++i) {
      std::uint8_t* d = dst + 4 * i;
      const std::uint8_t* s = src + 4 * i;
      const int dither = spec.dither ? dimx[static_cast<std::size_t>((x0 + static_cast<int>(i)) & 3)] : 0;
      for (int c = 0; c < 3; ++c) {
        const int v = blend16Channel(s[c], d[c], spec.fix, dither, spec.colclamp);
        delta = std::max(delta, std::abs(v - d[c]));
        d[c] = static_cast<std::uint8_t>(v);
      }
      if (!keepAlpha) {
        const int a = s[3] & 0x80;  // bit 7 of As is the texel's bit 15
        delta = std::max(delta, std::abs(a - d[3]));
        d[3] = static_cast<std::uint8_t>(a);
      }
    }
  }
  return delta;
}

}  // namespace vbim::gs
