// Colour space conversion as the IPU's CSC stage does it (P-IPU yuv2rgb.cpp and
// IPUdither.cpp): BT.601 integer matrix with coefficients x128 (0x95 = 1.164 x 128), each term >> 6
// (one extra bit kept), then (sum + 1) >> 1 and a clamp to 0..255 (bit-exact to PCSX2, unconfirmed on
// hardware); alpha 0x80 (1.0 for the GS); SETTH alpha thresholds; RGB16 5:5:5:1 with
// the 4x4 ordered dither; and the raw YCbCr planes for conformance checks.
#pragma once

#include <cstdint>
#include <vector>

#include "ipu/frame_store.hpp"
#include "runtime/image.hpp"

namespace vbim::ipu {

// SETTH (command 9): TH0 bits 0-8, TH1 bits 16-24.
struct CscThresholds {
  int th0 = 0;  // R, G, B all below TH0: the pixel becomes 0 (transparent black); 0 disables
  int th1 = 0;  // else R, G, B all below TH1: alpha 0x40 (translucent)
};

// One output line: `width` pixels from luma line y, chroma lines cb/cr (one chroma sample per two
// pixels) to RGBA8. This scalar code is the reference.
void cscRowRgba32Scalar(const std::uint8_t* y, const std::uint8_t* cb, const std::uint8_t* cr, int width,
                        std::uint8_t* rgba, CscThresholds th);
// `rows` (1 or 2) luma lines that share one chroma line. Implementations must give the bytes of
// cscRowRgba32Scalar on each line.
using CscRowFn = void (*)(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                          int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th);
void cscRowsRgba32Scalar(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                         int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th);

// The IPU matrix for one pixel (RGB only), exposed for tests and the RGB16 path.
struct Rgb {
  std::uint8_t r, g, b;
};
inline Rgb ipuYcbcrToRgb(int y, int cb, int cr) {
  const int lum = (0x95 * (y > 16 ? y - 16 : 0)) >> 6;  // Y bias 16, clamped at 0 (P-IPU saturating subtract)
  const int rcr = (0xCC * (cr - 128)) >> 6;
  const int gcr = (-0x68 * (cr - 128)) >> 6;
  const int gcb = (-0x32 * (cb - 128)) >> 6;
  const int bcb = (0x102 * (cb - 128)) >> 6;
  auto clamp = [](int v) { return static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v)); };
  return Rgb{clamp((lum + rcr + 1) >> 1), clamp((lum + gcr + gcb + 1) >> 1), clamp((lum + bcb + 1) >> 1)};
}

// Whole pictures from the frame store, cropped to width x height. `row` selects the line kernel
// (default: the scalar reference).
void convertToRgba32(const FrameStore& fs, int width, int height, CscThresholds th, Rgba8Image& out,
                     CscRowFn row = nullptr);
// Lines [y0, y1) of `out` (already sized; y0 even, y1 clipped to out.height), the same bytes as
// convertToRgba32 gives there: the slice-parallel decode converts each job's rows on its thread.
void convertLinesToRgba32(const FrameStore& fs, int y0, int y1, CscThresholds th, Rgba8Image& out,
                          CscRowFn row = nullptr);
// RGB16 (OFM = 1): bits 0-4 R, 5-9 G, 10-14 B, 15 alpha (set where the RGB32 alpha was 0x40).
void convertToRgb16(const FrameStore& fs, int width, int height, CscThresholds th, bool dither,
                    std::vector<std::uint16_t>& out);
void copyToYuv420(const FrameStore& fs, int width, int height, Yuv420Image& out);

}  // namespace vbim::ipu
