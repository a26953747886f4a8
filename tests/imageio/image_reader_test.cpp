// The full library: reading any format into the project's image types, and writing by extension
// (.png / .exr through the project's writers, others through OpenImageIO).
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "imageio/error.hpp"
#include "imageio/image_reader.hpp"
#include "imageio/image_writer.hpp"
#include "imageio/png_writer.hpp"
#include "imageio/rgba8.hpp"

namespace vbim::imageio {
namespace {

namespace fs = std::filesystem;

class ImageReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vbim_imageio_reader_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path path(const std::string& name) const { return dir_ / name; }

 private:
  fs::path dir_;
};

TEST_F(ImageReaderTest, Rgba8KeepsColoursUnderAnAlphaAndSetsTheGsOne) {
  // A frame as vbim play writes it: GS alpha 0x80 stored as is.
  Rgba8Image frame(3, 2);
  for (std::size_t i = 0; i < frame.pixels.size(); ++i) frame.pixels[i] = static_cast<std::uint8_t>(i * 11 + 5);
  for (std::size_t i = 3; i < frame.pixels.size(); i += 4) frame.pixels[i] = 0x80;
  writePng(path("frame.png"), rgbaView(frame));
  EXPECT_EQ(readRgba8(path("frame.png")).pixels, frame.pixels);
  // An RGB file: the same colours, alpha 0x80.
  writePng(path("frame_rgb.png"), rgbOf(frame).view());
  const Rgba8Image rgb = readRgba8(path("frame_rgb.png"));
  EXPECT_EQ(rgb.width, 3);
  EXPECT_EQ(rgb.pixels, frame.pixels);
}

TEST_F(ImageReaderTest, Rgba8RefusesGreyAndNamesTheFile) {
  const std::vector<std::uint8_t> grey(4, 9);
  writePng(path("grey.png"), ImageView<std::uint8_t>{2, 2, 1, grey.data()});
  try {
    readRgba8(path("grey.png"));
    FAIL();
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("grey.png: the image has 1 channel(s); expected an RGB"), std::string::npos)
        << e.what();
  }
}

TEST_F(ImageReaderTest, FloatRgbRepeatsGreyAndTellsFloatFilesApart) {
  const std::vector<std::uint8_t> grey = {0, 255};
  writePng(path("grey.png"), ImageView<std::uint8_t>{2, 1, 1, grey.data()});
  const FloatRgbFrame g = readFloatRgb(path("grey.png"));
  EXPECT_FALSE(g.floatingPoint);
  EXPECT_EQ(g.rgb.channels, 3);
  EXPECT_EQ(g.rgb.samples, (std::vector<float>{0, 0, 0, 1, 1, 1}));
  const std::vector<float> rgba = {0.5f, 2.0f, 0.25f, 1.0f};
  writeImage(path("hdr.exr"), ImageView<float>{1, 1, 4, rgba.data()});
  const FloatRgbFrame h = readFloatRgb(path("hdr.exr"));
  EXPECT_TRUE(h.floatingPoint);
  EXPECT_EQ(h.rgb.samples, (std::vector<float>{0.5f, 2.0f, 0.25f})) << "the fourth channel is dropped";
}

TEST_F(ImageReaderTest, IntegerFilesReadAsTheirOwnTypeGiveTheStoredCounts) {
  const std::vector<std::uint16_t> codes = {0, 1, 32768, 65535, 12345, 7};
  writeImage(path("codes.png"), ImageView<std::uint16_t>{3, 2, 1, codes.data()});
  ImageReader in(path("codes.png"), "horizon codes");
  EXPECT_EQ(in.info().stored, SampleType::UInt16);
  EXPECT_FALSE(in.info().floatingPoint);
  EXPECT_EQ(in.readUInt16().samples, codes);
}

TEST_F(ImageReaderTest, AHeaderClaimingAHugePictureIsRefusedBeforeReading) {
  // A 20000 x 20000 PNM header over 4 bytes of samples: 4e8 samples, more than kMaxImageSamples.
  {
    std::ofstream out(path("huge.pgm"), std::ios::binary);
    out << "P5\n20000 20000\n255\n" << std::string(4, '\x7f');
  }
  try {
    ImageReader in(path("huge.pgm"), "heightfield");
    FAIL() << "a 20000x20000 header was accepted";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.pgm: the heightfield is 20000x20000 with 1 channels, more than the "
                                         "268435456 samples"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ImageReaderTest, OtherExtensionsGoThroughOpenImageIo) {
  const std::vector<std::uint8_t> px = {1, 2, 3, 4, 5, 6};
  writeImage(path("a.tif"), ImageView<std::uint8_t>{2, 1, 3, px.data()});
  ImageReader in(path("a.tif"), "image");
  EXPECT_EQ(in.info().stored, SampleType::UInt8);
  EXPECT_EQ(in.readUInt8().samples, px);
  EXPECT_FALSE(fs::exists(path(".a.tmp.tif")));
}

TEST_F(ImageReaderTest, MismatchedFormatsAndUnreadableFilesAreClearErrors) {
  const std::vector<float> f(4, 0.5f);
  const std::vector<std::uint8_t> b(4, 1);
  EXPECT_THROW(writeImage(path("f.png"), ImageView<float>{2, 2, 1, f.data()}), ImageIoError);
  EXPECT_THROW(writeImage(path("b.exr"), ImageView<std::uint8_t>{2, 2, 1, b.data()}), ImageIoError);
  std::ofstream(path("junk.png")) << "nope";
  try {
    ImageReader in(path("junk.png"), "image");
    FAIL();
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.png: cannot read the image"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readFloatRgb(path("absent.exr")), ImageIoError);
}

}  // namespace
}  // namespace vbim::imageio
