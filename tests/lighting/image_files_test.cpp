// The lighting generator's files (moved here from the lighting tests with imageio): heightfields
// kept exact, float heights scaled, RGB heightfields and NaN heights refused with the file named,
// outputs written by extension under a temporary name. Inputs are written with OpenImageIO, an
// independent writer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "imageio/error.hpp"
#include "lighting/error.hpp"
#include "lighting/image_files.hpp"
#include "tests/lighting/oiio_scratch.hpp"

namespace vbim::lighting {
namespace {

using imageio::ImageIoError;

namespace fs = std::filesystem;

using testing::RemoveScratch;
using testing::scratch;
using testing::scratchDir;
using testing::writeRaw;
const auto* const kRemoveScratch = ::testing::AddGlobalTestEnvironment(new RemoveScratch);

TEST(LightingFiles, SixteenBitPngHeightsAreKeptExactly) {
  std::vector<std::uint16_t> v(6 * 4);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint16_t>(i * 2500);
  const fs::path p = scratch("hf16.png");
  writeRaw(p, 6, 4, 1, OIIO::TypeDesc::UINT16, v);
  const Terrain t = readHeightfield(p.string(), 5.0, 655.35);
  ASSERT_EQ(t.width, 6);
  ASSERT_EQ(t.height, 4);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(t.heights[i], v[i]);
  EXPECT_DOUBLE_EQ(t.heightStep, 0.01);
  EXPECT_DOUBLE_EQ(t.cellSize, 5.0);
}

TEST(LightingFiles, FloatExrHeightsAreMetresTimesScale) {
  std::vector<float> v = {0.0f, 1.5f, 100.25f, -3.0f};
  const fs::path p = scratch("hf.exr");
  writeRaw(p, 2, 2, 1, OIIO::TypeDesc::FLOAT, v);
  const Terrain t = readHeightfield(p.string(), 10.0, 2.0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(t.heights[i] * t.heightStep, v[i] * 2.0, 1.0 / 512);
}

TEST(LightingFiles, RejectsRgbHeightfieldsAndNaN) {
  const fs::path rgb = scratch("rgb.png");
  writeRaw(rgb, 4, 4, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(48, 7));
  try {
    readHeightfield(rgb.string(), 10, 100);
    FAIL();
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("rgb.png: the heightfield has 3 channels; expected a single-channel"),
              std::string::npos)
        << e.what();
  }
  const fs::path nan = scratch("nan.exr");
  std::vector<float> v(9, 1.0f);
  v[5] = std::nanf("");
  writeRaw(nan, 3, 3, 1, OIIO::TypeDesc::FLOAT, v);
  try {
    readHeightfield(nan.string(), 10, 1);
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.exr: height at pixel (2, 1) is NaN"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readHeightfield(scratch("missing.png").string(), 10, 1), ImageIoError);
  std::ofstream(scratch("garbage.png")) << "not an image";
  EXPECT_THROW(readHeightfield(scratch("garbage.png").string(), 10, 1), ImageIoError);
}

TEST(LightingFiles, WritesExrAndPngRoundTrip) {
  FloatImage img(3, 2, 3);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = static_cast<float>(i) / 17.0f;
  writeImage(scratch("out.exr"), img);
  writeImage(scratch("out.png"), img);
  auto in = OIIO::ImageInput::open(scratch("out.exr").string());
  ASSERT_TRUE(in);
  std::vector<float> back(img.pixels.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()));
  EXPECT_EQ(back, img.pixels);
  auto png = OIIO::ImageInput::open(scratch("out.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> bytes(img.pixels.size());
  ASSERT_TRUE(png->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
  for (std::size_t i = 0; i < bytes.size(); ++i)
    EXPECT_EQ(bytes[i], static_cast<int>(std::lround(std::min(1.0f, img.pixels[i]) * 255.0f))) << i;
  EXPECT_FALSE(fs::exists(scratch(".out.tmp.png")));
}

TEST(LightingFiles, ColourMapsAreLinearisedAndCloudTexturesClamped) {
  const fs::path srgb = scratch("albedo.png"), linear = scratch("albedo.exr"), clouds = scratch("clouds.exr");
  writeRaw(srgb, 2, 1, 1, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>{0, 255});
  const FloatImage a = readColourMap(srgb.string());
  ASSERT_EQ(a.channels, 3);
  EXPECT_EQ(a.pixels, (std::vector<float>{0, 0, 0, 1, 1, 1})) << "grey is repeated; 8-bit is sRGB-decoded";
  writeRaw(linear, 1, 1, 3, OIIO::TypeDesc::FLOAT, std::vector<float>{0.25f, 0.5f, 2.0f});
  EXPECT_EQ(readColourMap(linear.string()).pixels, (std::vector<float>{0.25f, 0.5f, 2.0f})) << "floats are linear";
  writeRaw(clouds, 3, 1, 1, OIIO::TypeDesc::FLOAT, std::vector<float>{-1.0f, 0.5f, 3.0f});
  EXPECT_EQ(readDensityMap(clouds.string()).pixels, (std::vector<float>{0.0f, 0.5f, 1.0f}));
  try {
    readDensityMap(linear.string());
    FAIL();
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("albedo.exr: the cloud texture has 3 channels"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vbim::lighting
