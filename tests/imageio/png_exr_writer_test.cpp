// The lean writers (libpng, OpenEXR) against an independent reader (OpenImageIO): what is written
// is what comes back, nothing is left under a temporary name, and failures name the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "imageio/error.hpp"
#include "imageio/exr_writer.hpp"
#include "imageio/png_writer.hpp"

namespace vbim::imageio {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  fs::path d = fs::temp_directory_path() / ("vbim_imageio_writer_" + std::to_string(::getpid()));
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

// The samples as stored (OpenImageIO would otherwise multiply colours by alpha).
template <typename T>
std::vector<T> readStored(const fs::path& p, OIIO::TypeDesc type, int channels, OIIO::TypeDesc* stored = nullptr) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(p.string(), &config);
  if (!in || in->spec().nchannels != channels) return {};
  if (stored != nullptr) *stored = in->spec().format;
  std::vector<T> back(static_cast<std::size_t>(in->spec().width) * in->spec().height * channels);
  if (!in->read_image(0, 0, 0, channels, type, back.data())) return {};
  return back;
}

bool onlyFinalFiles(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return false;
  return true;
}

TEST(ImageIoWriters, PngRoundTripsEveryByte) {
  const fs::path dir = scratch();
  const int w = 37, h = 11;  // odd sizes: no row padding assumed
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>((i * 37 + i / 5) & 0xFF);
  writePng(dir / "a.png", ImageView<std::uint8_t>{w, h, 4, rgba.data()});
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
  EXPECT_TRUE(onlyFinalFiles(dir));
  fs::remove_all(dir);
}

TEST(ImageIoWriters, PngOfEveryChannelCountAndSpeedKeepsTheBytes) {
  const fs::path dir = scratch();
  const int w = 9, h = 5;
  for (int channels = 1; channels <= 4; ++channels) {
    for (const PngSpeed speed : {PngSpeed::Default, PngSpeed::Fast}) {
      std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * channels);
      for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint8_t>(i * 13 + channels);
      const fs::path p = dir / ("c" + std::to_string(channels) + ".png");
      writePng(p, ImageView<std::uint8_t>{w, h, channels, px.data()}, speed);
      EXPECT_EQ(readStored<std::uint8_t>(p, OIIO::TypeDesc::UINT8, channels), px) << channels << " channel(s)";
    }
  }
  fs::remove_all(dir);
}

TEST(ImageIoWriters, SixteenBitPngKeepsTheCountsExactly) {
  const fs::path dir = scratch();
  const int w = 7, h = 3;
  for (const int channels : {1, 3}) {
    std::vector<std::uint16_t> px(static_cast<std::size_t>(w) * h * channels);
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint16_t>(i * 3119 + 1);
    const fs::path p = dir / "codes.png";
    writePng(p, ImageView<std::uint16_t>{w, h, channels, px.data()});
    OIIO::TypeDesc stored;
    EXPECT_EQ(readStored<std::uint16_t>(p, OIIO::TypeDesc::UINT16, channels, &stored), px);
    EXPECT_EQ(stored, OIIO::TypeDesc::UINT16);
  }
  const std::vector<std::uint16_t> ga(8, 1);
  EXPECT_THROW(writePng(dir / "ga.png", ImageView<std::uint16_t>{2, 2, 2, ga.data()}), ImageIoError)
      << "16-bit alpha would be taken as premultiplied by libpng";
  fs::remove_all(dir);
}

TEST(ImageIoWriters, ExrRoundTripsWithinHalfPrecision) {
  const fs::path dir = scratch();
  const int w = 19, h = 7;
  std::vector<float> rgba(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<float>(i % 256) / 255.0f;
  writeExr(dir / "a.exr", ImageView<float>{w, h, 4, rgba.data()});
  int rw = 0, rh = 0, channels = 0;
  const std::vector<float> back = readFloats(dir / "a.exr", rw, rh, channels);
  ASSERT_EQ(rw, w);
  ASSERT_EQ(rh, h);
  ASSERT_EQ(channels, 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) ASSERT_NEAR(back[i], rgba[i], 1.0 / 1024) << i;  // 10-bit mantissa
  EXPECT_TRUE(onlyFinalFiles(dir));
  fs::remove_all(dir);
}

TEST(ImageIoWriters, FloatExrKeepsEveryValueAndGreyIsOneChannel) {
  const fs::path dir = scratch();
  const int w = 5, h = 4;
  for (const int channels : {1, 3}) {
    std::vector<float> px(static_cast<std::size_t>(w) * h * channels);
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<float>(i) / 17.0f - 0.3f;
    writeExr(dir / "f.exr", ImageView<float>{w, h, channels, px.data()}, ExrSamples::Float);
    OIIO::TypeDesc stored;
    EXPECT_EQ(readStored<float>(dir / "f.exr", OIIO::TypeDesc::FLOAT, channels, &stored), px) << channels;
    EXPECT_EQ(stored, OIIO::TypeDesc::FLOAT);
  }
  fs::remove_all(dir);
}

TEST(ImageIoWriters, FailuresNameTheFileAndLeaveNothing) {
  const std::vector<std::uint8_t> px(16, 0);
  const std::vector<float> fx(16, 0.0f);
  const fs::path missing = fs::temp_directory_path() / "vbim_no_such_dir" / "x.png";
  try {
    writePng(missing, ImageView<std::uint8_t>{2, 2, 4, px.data()});
    FAIL() << "expected an error";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  try {
    writeExr(missing.string() + ".exr", ImageView<float>{2, 2, 4, fx.data()});
    FAIL() << "expected an error";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("x.png.exr"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writePng(fs::temp_directory_path() / "vbim_zero.png", ImageView<std::uint8_t>{0, 4, 4, px.data()}),
               ImageIoError);
  EXPECT_THROW(writePng(fs::temp_directory_path() / "vbim_five.png", ImageView<std::uint8_t>{1, 1, 5, px.data()}),
               ImageIoError);
  // A directory where the file should go: the write succeeds under the temporary name, the rename
  // fails, and the temporary file is removed.
  const fs::path dir = scratch();
  fs::create_directories(dir / "taken.png" / "inside");
  EXPECT_THROW(writePng(dir / "taken.png", ImageView<std::uint8_t>{2, 2, 4, px.data()}), ImageIoError);
  EXPECT_TRUE(onlyFinalFiles(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::imageio
