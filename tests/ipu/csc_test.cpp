// Colour conversion with the PS2 integer matrix, SETTH thresholds and RGB16 dither
// (docs/hardware.md#colour-conversion).
#include "ipu/csc.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vbim::ipu {
namespace {

FrameStore flat(int y, int cb, int cr) {
  FrameStore fs;
  fs.reset(1, 1);
  std::fill(fs.y.begin(), fs.y.end(), static_cast<std::uint8_t>(y));
  std::fill(fs.cb.begin(), fs.cb.end(), static_cast<std::uint8_t>(cb));
  std::fill(fs.cr.begin(), fs.cr.end(), static_cast<std::uint8_t>(cr));
  return fs;
}

TEST(IpuCsc, BlackWhiteAndVideoRange) {
  EXPECT_EQ(ipuYcbcrToRgb(16, 128, 128).r, 0);
  EXPECT_EQ(ipuYcbcrToRgb(0, 128, 128).g, 0);  // below the Y bias clamps, no wrap
  const Rgb w = ipuYcbcrToRgb(235, 128, 128);
  EXPECT_EQ(w.r, 255);
  EXPECT_EQ(w.g, 255);
  EXPECT_EQ(w.b, 255);
  // Mid grey: lum = (112 * 0x95) >> 6 = 260, (260 + 1) >> 1 = 130.
  EXPECT_EQ(ipuYcbcrToRgb(128, 128, 128).r, 130);
}

// The integer matrix stays within 1.5 of BT.601 in floating point everywhere it does not clip.
TEST(IpuCsc, TracksBt601) {
  for (int y = 16; y <= 235; y += 3)
    for (int cb = 16; cb <= 240; cb += 7)
      for (int cr = 16; cr <= 240; cr += 7) {
        const Rgb c = ipuYcbcrToRgb(y, cb, cr);
        const double r = 1.164 * (y - 16) + 1.596 * (cr - 128);
        const double g = 1.164 * (y - 16) - 0.813 * (cr - 128) - 0.391 * (cb - 128);
        const double b = 1.164 * (y - 16) + 2.018 * (cb - 128);
        auto near = [](double f, int v) { return f < 0 || f > 255 || std::fabs(f - v) <= 1.5; };
        ASSERT_TRUE(near(r, c.r) && near(g, c.g) && near(b, c.b)) << y << " " << cb << " " << cr;
      }
}

TEST(IpuCsc, Rgb32AlphaIs0x80AndRowsUseHalfResolutionChroma) {
  FrameStore fs;
  fs.reset(1, 1);
  for (int i = 0; i < 256; ++i) fs.y[i] = static_cast<std::uint8_t>(i);
  for (int i = 0; i < 64; ++i) {
    fs.cb[i] = static_cast<std::uint8_t>(100 + i);
    fs.cr[i] = static_cast<std::uint8_t>(200 - i);
  }
  Rgba8Image img;
  convertToRgba32(fs, 15, 13, {}, img);
  ASSERT_EQ(img.width, 15);
  for (int y = 0; y < 13; ++y)
    for (int x = 0; x < 15; ++x) {
      const Rgb c = ipuYcbcrToRgb(fs.y[y * 16 + x], fs.cb[(y / 2) * 8 + x / 2], fs.cr[(y / 2) * 8 + x / 2]);
      const std::uint8_t* p = img.row(y) + 4 * x;
      ASSERT_EQ(p[0], c.r);
      ASSERT_EQ(p[1], c.g);
      ASSERT_EQ(p[2], c.b);
      ASSERT_EQ(p[3], 0x80);
    }
}

TEST(IpuCsc, SetthThresholds) {
  Rgba8Image img;
  // Dark pixel (RGB ~ 20): below TH0 = 40 -> transparent black.
  convertToRgba32(flat(33, 128, 128), 16, 16, {40, 100}, img);
  EXPECT_EQ(img.row(0)[0], 0);
  EXPECT_EQ(img.row(0)[3], 0);
  // Mid pixel (~ 76): not below TH0, below TH1 -> alpha 0x40, colour kept.
  convertToRgba32(flat(81, 128, 128), 16, 16, {40, 100}, img);
  EXPECT_EQ(img.row(0)[3], 0x40);
  EXPECT_GT(img.row(0)[0], 70);
  // TH0 = 0 disables the first test.
  convertToRgba32(flat(16, 128, 128), 16, 16, {0, 100}, img);
  EXPECT_EQ(img.row(0)[3], 0x40);
  // A pixel with one channel above TH1 stays opaque.
  convertToRgba32(flat(81, 128, 240), 16, 16, {40, 100}, img);
  EXPECT_EQ(img.row(0)[3], 0x80);
}

TEST(IpuCsc, Rgb16LayoutAndOrderedDither) {
  const FrameStore fs = flat(128, 128, 128);  // RGB 130 everywhere
  std::vector<std::uint16_t> plain, dithered;
  convertToRgb16(fs, 16, 16, {}, false, plain);
  EXPECT_EQ(plain[0], (130 >> 3) | ((130 >> 3) << 5) | ((130 >> 3) << 10));
  convertToRgb16(fs, 16, 16, {}, true, dithered);
  static constexpr int kD[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const int v = (130 + kD[y & 3][x & 3]) >> 3;
      EXPECT_EQ(dithered[y * 16 + x], v | (v << 5) | (v << 10));
    }
  // The alpha bit marks SETTH's translucent pixels.
  convertToRgb16(flat(81, 128, 128), 16, 16, {0, 100}, false, plain);
  EXPECT_EQ(plain[0] >> 15, 1);
}

TEST(IpuCsc, Yuv420CropsThePaddedStore) {
  FrameStore fs;
  fs.reset(2, 1);
  for (std::size_t i = 0; i < fs.y.size(); ++i) fs.y[i] = static_cast<std::uint8_t>(i);
  Yuv420Image out;
  copyToYuv420(fs, 17, 9, out);
  EXPECT_EQ(out.chromaWidth(), 9);
  EXPECT_EQ(out.y[17], fs.y[32]);  // second line starts at the store's second line
}

}  // namespace
}  // namespace vbim::ipu
