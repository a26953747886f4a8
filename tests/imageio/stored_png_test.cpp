// The level-0 PNG written without libpng (imageio/stored_png.hpp, issue #31) is libpng's, byte for
// byte: the same zlib header, stored blocks of the same lengths, the same checksums, over shapes
// that reach every case of how zlib cuts the rows into blocks (one block under 16 KiB with the
// smaller windows' headers, the 32 KiB threshold reached exactly and passed by a row, rows longer
// than a block, a final empty block). And libpng reads the samples back from it.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <string>
#include <vector>

#include "imageio/png_encoder.hpp"
#include "imageio/rgb_pack.hpp"
#include "imageio/stored_png.hpp"
#include "tests/imageio/libpng_decode.hpp"

namespace vbim::imageio {
namespace {

// Samples that differ from row to row and sample to sample, so a misplaced byte shows.
Image<std::uint8_t> picture(int w, int h, int channels, std::uint32_t seed) {
  Image<std::uint8_t> img(w, h, channels);
  std::uint32_t noise = seed;
  for (std::uint8_t& s : img.samples) {
    noise = noise * 1664525u + 1013904223u;
    s = static_cast<std::uint8_t>(noise >> 24);
  }
  return img;
}

std::string shape(int w, int h, int channels) {
  return std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(channels);
}

// libpng's reading of the bytes in the channel layout they were written with; empty if it fails.
std::vector<std::uint8_t> decode(const std::vector<std::uint8_t>& png, int channels) {
  return testing::decodeWithLibpng(png, channels);
}

void expectLibpngsBytes(int w, int h, int channels) {
  const Image<std::uint8_t> img = picture(w, h, channels, static_cast<std::uint32_t>(w * 7919 + h * 31 + channels));
  ASSERT_TRUE(fitsStoredPng(img.view())) << shape(w, h, channels);
  const std::vector<std::uint8_t> libpng = encodePngWithLibpng(img.view(), 0, "x.png");
  std::vector<std::uint8_t> ours(storedPngSize(img.view()));
  writeStoredPng(img.view(), ours.data());
  ASSERT_EQ(ours.size(), libpng.size()) << shape(w, h, channels);
  EXPECT_TRUE(ours == libpng) << shape(w, h, channels);
  EXPECT_EQ(encodePng(img.view(), 0, "x.png"), libpng) << shape(w, h, channels);
}

// The RGB of RGBA texels packed as the rows are written (the path opaque frames take) is libpng's
// file of the RGB packed byte by byte beforehand: the blocks now cut the packed rows inside texels.
void expectLibpngsBytesOfRgb(int w, int h) {
  const Image<std::uint8_t> rgba =
      picture(w, h, 4, static_cast<std::uint32_t>(w) * 104729u + static_cast<std::uint32_t>(h));
  Image<std::uint8_t> rgb(w, h, 3);
  packRgbOfRgbaReference(rgba.samples.data(), rgba.samples.size() / 4, rgb.samples.data());
  const std::vector<std::uint8_t> libpng = encodePngWithLibpng(rgb.view(), 0, "x.png");
  ASSERT_TRUE(fitsStoredPng(rgba.view(), FileChannels::RgbOfRgba)) << shape(w, h, 4);
  ASSERT_EQ(storedPngSize(rgba.view(), FileChannels::RgbOfRgba), libpng.size()) << shape(w, h, 4);
  std::vector<std::uint8_t> ours(libpng.size());
  writeStoredPng(rgba.view(), ours.data(), FileChannels::RgbOfRgba);
  EXPECT_TRUE(ours == libpng) << shape(w, h, 4);
  EXPECT_EQ(encodePng(rgba.view(), 0, "x.png", FileChannels::RgbOfRgba), libpng) << shape(w, h, 4);
  // Levels 1 to 9 hand libpng the packed samples.
  EXPECT_EQ(encodePng(rgba.view(), 1, "x.png", FileChannels::RgbOfRgba), encodePng(rgb.view(), 1, "x.png"))
      << shape(w, h, 4);
}

TEST(StoredPng, TheBytesAreLibpngsForEveryChannelCount) {
  for (int channels = 1; channels <= 4; ++channels) {
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{
             {1, 1}, {2, 1}, {1, 2}, {3, 5}, {17, 13}, {37, 23}, {63, 64}, {128, 64}, {255, 1}, {256, 256}, {257, 3}}) {
      expectLibpngsBytes(w, h, channels);
    }
  }
}

// The zlib header shrinks with libpng's window for data of at most 16 KiB: every boundary.
TEST(StoredPng, SmallPicturesHaveLibpngsWindowInTheHeader) {
  for (const int data : {2,    255,  256,  257,  258,   512,   513,   1024,  1025,  2048,  2049,
                         4096, 4097, 8192, 8193, 16383, 16384, 16385, 16386, 32767, 32768, 32769}) {
    expectLibpngsBytes(data - 1, 1, 1);  // one grey row: its filter byte and data - 1 samples
  }
  for (const int rows : {1, 2, 3, 16, 63, 64, 65, 128}) expectLibpngsBytes(127, rows, 1);  // 128 bytes a row
}

// Data of 32 KiB and more: where the rows reach zlib's 32 KiB (exactly, or passed by a row that
// then crosses a block boundary), rows longer than a stored block, several blocks, the final one
// empty or not.
TEST(StoredPng, LargePicturesAreCutIntoLibpngsBlocks) {
  const std::vector<std::pair<int, int>> shapes = {
      {8191, 8},   // rows of 32,765 bytes (RGBA): each block two rows
      {8192, 4},   // rows of 32,769: one row reaches the threshold alone
      {511, 128},  // rows of 2,045: the threshold passed mid-row
      {4095, 9},   // rows of 16,381
      {16383, 3},  // rows of 65,533, under one block
      {16384, 3},  // rows of 65,537, two bytes over one block
      {20000, 3},  // rows of 80,001: a block and a remainder past the threshold
      {40000, 2},  // rows of 160,001: several full blocks a row
      {300, 300},  // 360,300 bytes, 11 blocks
  };
  for (const auto& [w, h] : shapes) expectLibpngsBytes(w, h, 4);
  // Grey rows of 32,767 and 32,768 bytes: one under and one at the threshold, alone.
  for (const int w : {32766, 32767}) expectLibpngsBytes(w, 3, 1);
  // Odd widths at every channel count across the first blocks.
  for (int channels = 1; channels <= 4; ++channels) {
    for (const int w : {331, 997, 2731}) expectLibpngsBytes(w, 40, channels);
  }
}

// A sweep of widths at a height that takes the data over several blocks: every offset at which a
// row can cross a block boundary, for each channel count.
TEST(StoredPng, EveryRowLengthInASweepIsLibpngs) {
  for (int channels = 1; channels <= 4; ++channels) {
    for (int w = 1; w <= 700; w += 23) expectLibpngsBytes(w, 16'000 / (w * channels + 1) + 45, channels);
  }
}

// Every offset in a texel at which a block can begin or end, over widths whose packed rows take the
// data over several blocks, and the demo's picture sizes.
TEST(StoredPng, RgbOfRgbaIsLibpngsFileOfThePackedSamples) {
  for (int w = 1; w <= 700; w += 23) expectLibpngsBytesOfRgb(w, 16'000 / (w * 3 + 1) + 45);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{
           {1, 1}, {2, 3}, {256, 256}, {128, 64}, {512, 512}, {256, 128}, {21845, 3}, {21846, 2}, {30000, 2}}) {
    expectLibpngsBytesOfRgb(w, h);
  }
  const std::uint8_t sample = 0;
  EXPECT_FALSE(fitsStoredPng({4, 4, 3, &sample}, FileChannels::RgbOfRgba));  // RGBA needed
}

TEST(StoredPng, LibpngReadsTheSamplesBack) {
  for (int channels = 1; channels <= 4; ++channels) {
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {37, 23}, {256, 256}, {20000, 3}}) {
      const Image<std::uint8_t> img = picture(w, h, channels, 99);
      std::vector<std::uint8_t> png(storedPngSize(img.view()));
      writeStoredPng(img.view(), png.data());
      EXPECT_EQ(decode(png, channels), img.samples) << shape(w, h, channels);
    }
  }
}

// What it leaves to libpng: a side past libpng's million (which libpng refuses), no samples, more
// than 4 channels.
TEST(StoredPng, ShapesLeftToLibpng) {
  const std::uint8_t sample = 0;
  EXPECT_TRUE(fitsStoredPng({1'000'000, 1, 1, &sample}));
  EXPECT_FALSE(fitsStoredPng({1'000'001, 1, 1, &sample}));
  EXPECT_FALSE(fitsStoredPng({1, 1'000'001, 1, &sample}));
  EXPECT_FALSE(fitsStoredPng({0, 1, 1, &sample}));
  EXPECT_FALSE(fitsStoredPng({1, 1, 5, &sample}));
  EXPECT_FALSE(fitsStoredPng({1, 1, 0, &sample}));
  // Past 2^31 - 1 bytes of rows libpng splits the data over several IDAT chunks.
  EXPECT_FALSE(fitsStoredPng({1'000'000, 1'000, 4, &sample}));
}

}  // namespace
}  // namespace vbim::imageio
