// Plain image buffers passed between stages (IPU output -> GS upload, GS lightmap -> outputs).
// Row-major, tightly packed, no padding: stride = width * channels.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vbim {

// 8-bit RGBA, as the IPU's RGB32 output and the GS's PSMCT32 texels (alpha 0x80 = 1.0).
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4 bytes, R G B A

  Rgba8Image() = default;
  Rgba8Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* row(int y) { return pixels.data() + static_cast<std::size_t>(y) * width * 4; }
  const std::uint8_t* row(int y) const { return pixels.data() + static_cast<std::size_t>(y) * width * 4; }
  bool sameSize(const Rgba8Image& o) const { return width == o.width && height == o.height; }
};

// 8-bit planar YCbCr 4:2:0 (raw IPU output for conformance checks). Chroma planes are
// ceil(width/2) x ceil(height/2).
struct Yuv420Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> y, cb, cr;

  Yuv420Image() = default;
  Yuv420Image(int w, int h)
      : width(w),
        height(h),
        y(static_cast<std::size_t>(w) * h),
        cb(static_cast<std::size_t>((w + 1) / 2) * ((h + 1) / 2)),
        cr(static_cast<std::size_t>((w + 1) / 2) * ((h + 1) / 2)) {}
  int chromaWidth() const { return (width + 1) / 2; }
  int chromaHeight() const { return (height + 1) / 2; }
};

}  // namespace vbim
