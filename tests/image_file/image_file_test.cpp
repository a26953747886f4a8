// The lean image writer against an independent reader (OpenImageIO): what is written is what
// comes back, and failures name the file.
#include "runtime/image_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace vbim {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  fs::path d = fs::temp_directory_path() / ("vbim_image_file_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<float> readFloats(const fs::path& p, int& w, int& h, int& channels) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  w = spec.width;
  h = spec.height;
  channels = spec.nchannels;
  std::vector<float> px(static_cast<std::size_t>(w) * h * channels);
  in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

TEST(ImageFile, PngRoundTripsEveryByte) {
  const fs::path dir = scratch();
  const int w = 37, h = 11;  // odd sizes: no row padding assumed
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>((i * 37 + i / 5) & 0xFF);
  writePng(dir / "a.png", w, h, rgba.data());
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // the bytes as stored, not multiplied by alpha
  auto in = OIIO::ImageInput::open((dir / "a.png").string(), &config);
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().width, w);
  ASSERT_EQ(in->spec().height, h);
  ASSERT_EQ(in->spec().nchannels, 4);
  std::vector<std::uint8_t> back(rgba.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, rgba);
  fs::remove_all(dir);
}

TEST(ImageFile, ExrRoundTripsWithinHalfPrecision) {
  const fs::path dir = scratch();
  const int w = 19, h = 7;
  std::vector<float> rgba(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<float>(i % 256) / 255.0f;
  writeExr(dir / "a.exr", w, h, rgba.data());
  int rw = 0, rh = 0, channels = 0;
  const std::vector<float> back = readFloats(dir / "a.exr", rw, rh, channels);
  ASSERT_EQ(rw, w);
  ASSERT_EQ(rh, h);
  ASSERT_EQ(channels, 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) ASSERT_NEAR(back[i], rgba[i], 1.0 / 1024) << i;  // 10-bit mantissa
  fs::remove_all(dir);
}

TEST(ImageFile, FailuresNameTheFile) {
  const std::vector<std::uint8_t> px(16, 0);
  const std::vector<float> fx(16, 0.0f);
  const fs::path missing = fs::temp_directory_path() / "vbim_no_such_dir" / "x.png";
  try {
    writePng(missing, 2, 2, px.data());
    FAIL() << "expected an error";
  } catch (const ImageFileError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  try {
    writeExr(missing.string() + ".exr", 2, 2, fx.data());
    FAIL() << "expected an error";
  } catch (const ImageFileError& e) {
    EXPECT_NE(std::string(e.what()).find("x.png.exr"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writePng(fs::temp_directory_path() / "vbim_zero.png", 0, 4, px.data()), ImageFileError);
}

}  // namespace
}  // namespace vbim
