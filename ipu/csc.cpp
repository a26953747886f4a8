#include "ipu/csc.hpp"

#include <cstddef>
#include <cstring>

namespace vbim::ipu {
namespace {

// 4x4 ordered dither of the RGB16 path (P-IPU IPUdither.cpp; docs/hardware.md#colour-conversion), [y & 3][x & 3].
constexpr int kDither[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};

// Alpha of a converted pixel under SETTH; 0 means the whole pixel is cleared.
inline int thresholdAlpha(int r, int g, int b, CscThresholds th) {
  const int m = r > g ? (r > b ? r : b) : (g > b ? g : b);  // all below T <=> max below T
  if (m < th.th0) return 0;
  if (m < th.th1) return 0x40;
  return 0x80;
}

}  // namespace

void cscRowRgba32Scalar(const std::uint8_t* y, const std::uint8_t* cb, const std::uint8_t* cr, int width,
                        std::uint8_t* rgba, CscThresholds th) {
  for (int x = 0; x < width; ++x) {
    const Rgb c = ipuYcbcrToRgb(y[x], cb[x >> 1], cr[x >> 1]);
    const int a = thresholdAlpha(c.r, c.g, c.b, th);
    std::uint8_t* o = rgba + 4 * static_cast<std::ptrdiff_t>(x);
    if (a == 0) {
      o[0] = o[1] = o[2] = o[3] = 0;
    } else {
      o[0] = c.r;
      o[1] = c.g;
      o[2] = c.b;
      o[3] = static_cast<std::uint8_t>(a);
    }
  }
}

void cscRowsRgba32Scalar(const std::uint8_t* y, int yStride, int rows, const std::uint8_t* cb, const std::uint8_t* cr,
                         int width, std::uint8_t* rgba, int rgbaStride, CscThresholds th) {
  for (int r = 0; r < rows; ++r) {
    cscRowRgba32Scalar(y + static_cast<std::ptrdiff_t>(r) * yStride, cb, cr, width,
                       rgba + static_cast<std::ptrdiff_t>(r) * rgbaStride, th);
  }
}

void convertToRgba32(const FrameStore& fs, int width, int height, CscThresholds th, Rgba8Image& out, CscRowFn row) {
  if (out.width != width || out.height != height) out = Rgba8Image(width, height);
  convertLinesToRgba32(fs, 0, height, th, out, row);
}

void convertLinesToRgba32(const FrameStore& fs, int y0, int y1, CscThresholds th, Rgba8Image& out, CscRowFn row) {
  if (!row) row = cscRowsRgba32Scalar;
  const int height = y1 < out.height ? y1 : out.height;
  for (int yy = y0; yy < height; yy += 2) {
    const std::uint8_t* yl = fs.y.data() + static_cast<std::size_t>(yy) * fs.lumaStride;
    const std::size_t c = static_cast<std::size_t>(yy >> 1) * fs.chromaStride;
    row(yl, fs.lumaStride, height - yy >= 2 ? 2 : 1, fs.cb.data() + c, fs.cr.data() + c, out.width, out.row(yy),
        out.width * 4, th);
  }
}

void convertToRgb16(const FrameStore& fs, int width, int height, CscThresholds th, bool dither,
                    std::vector<std::uint16_t>& out) {
  out.assign(static_cast<std::size_t>(width) * height, 0);
  std::vector<std::uint8_t> line(static_cast<std::size_t>(width) * 4);
  for (int yy = 0; yy < height; ++yy) {
    const std::size_t c = static_cast<std::size_t>(yy >> 1) * fs.chromaStride;
    cscRowRgba32Scalar(fs.y.data() + static_cast<std::size_t>(yy) * fs.lumaStride, fs.cb.data() + c, fs.cr.data() + c,
                       width, line.data(), th);
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = line.data() + 4 * static_cast<std::ptrdiff_t>(x);
      int v[3];
      for (int k = 0; k < 3; ++k) {
        int s = p[k];
        if (dither) {
          s += kDither[yy & 3][x & 3];
          s = s < 0 ? 0 : (s > 255 ? 255 : s);
        }
        v[k] = s >> 3;
      }
      const int alphaBit = p[3] == 0x40 ? 1 : 0;
      out[static_cast<std::size_t>(yy) * width + x] =
          static_cast<std::uint16_t>(v[0] | (v[1] << 5) | (v[2] << 10) | (alphaBit << 15));
    }
  }
}

void copyToYuv420(const FrameStore& fs, int width, int height, Yuv420Image& out) {
  if (out.width != width || out.height != height) out = Yuv420Image(width, height);
  for (int yy = 0; yy < height; ++yy) {
    std::memcpy(out.y.data() + static_cast<std::size_t>(yy) * width,
                fs.y.data() + static_cast<std::size_t>(yy) * fs.lumaStride, static_cast<std::size_t>(width));
  }
  const int cw = out.chromaWidth(), ch = out.chromaHeight();
  for (int yy = 0; yy < ch; ++yy) {
    std::memcpy(out.cb.data() + static_cast<std::size_t>(yy) * cw,
                fs.cb.data() + static_cast<std::size_t>(yy) * fs.chromaStride, static_cast<std::size_t>(cw));
    std::memcpy(out.cr.data() + static_cast<std::size_t>(yy) * cw,
                fs.cr.data() + static_cast<std::size_t>(yy) * fs.chromaStride, static_cast<std::size_t>(cw));
  }
}

}  // namespace vbim::ipu
