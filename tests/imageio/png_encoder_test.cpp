// The frames' PNG encoder (imageio/png_encoder.hpp, issue #31) against independent readers (libpng,
// OpenImageIO): every level and channel count gives back the samples exactly, the container is
// libpng's simplified API's (IHDR, sRGB, one IDAT, IEND), level 0 stores every row, the bytes do not depend on the
// thread or on what was encoded before, and failures name the file and leave nothing behind.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "imageio/error.hpp"
#include "imageio/png_encoder.hpp"
#include "tests/imageio/libpng_decode.hpp"

namespace vbim::imageio {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  fs::path d = fs::temp_directory_path() / ("vbim_png_encoder_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// Smooth gradients with noise: what a lightmap looks like to the row filters.
Image<std::uint8_t> picture(int w, int h, int channels) {
  Image<std::uint8_t> img(w, h, channels);
  std::uint32_t noise = 12345;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < channels; ++c) {
        noise = noise * 1664525u + 1013904223u;
        const std::size_t i = (static_cast<std::size_t>(y) * w + x) * channels + c;
        img.samples[i] = static_cast<std::uint8_t>(x * 3 + y * (c + 1) + (noise >> 29));
      }
    }
  }
  return img;
}

// libpng's reading of the bytes, in the channel layout they were written with.
std::vector<std::uint8_t> decode(const std::vector<std::uint8_t>& png, int channels, int& w, int& h) {
  return testing::decodeWithLibpng(png, channels, &w, &h);
}

std::vector<std::string> chunkTypes(const std::vector<std::uint8_t>& png) {
  std::vector<std::string> types;
  for (std::size_t i = 8; i + 8 <= png.size();) {
    const std::size_t length = (std::size_t{png[i]} << 24) | (std::size_t{png[i + 1]} << 16) |
                               (std::size_t{png[i + 2]} << 8) | std::size_t{png[i + 3]};
    types.emplace_back(png.begin() + static_cast<std::ptrdiff_t>(i + 4),
                       png.begin() + static_cast<std::ptrdiff_t>(i + 8));
    i += 12 + length;
  }
  return types;
}

std::vector<std::uint8_t> slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(PngEncoder, EveryLevelAndChannelCountGivesTheSamplesBack) {
  for (int channels = 1; channels <= 4; ++channels) {
    const Image<std::uint8_t> img = picture(37, 23, channels);
    for (const int level : {0, 1, 6, kMaxPngLevel}) {
      const std::vector<std::uint8_t> png = encodePng(img.view(), level, "x.png");
      int w = 0;
      int h = 0;
      EXPECT_EQ(decode(png, channels, w, h), img.samples) << channels << " channel(s), level " << level;
      EXPECT_EQ(w, 37);
      EXPECT_EQ(h, 23);
      EXPECT_EQ(chunkTypes(png), (std::vector<std::string>{"IHDR", "sRGB", "IDAT", "IEND"}));
    }
  }
}

// The data of the one IDAT chunk (chunkTypes checks there is one).
std::vector<std::uint8_t> idatData(const std::vector<std::uint8_t>& png) {
  for (std::size_t i = 8; i + 8 <= png.size();) {
    const std::size_t length = (std::size_t{png[i]} << 24) | (std::size_t{png[i + 1]} << 16) |
                               (std::size_t{png[i + 2]} << 8) | std::size_t{png[i + 3]};
    if (std::string(png.begin() + static_cast<std::ptrdiff_t>(i + 4),
                    png.begin() + static_cast<std::ptrdiff_t>(i + 8)) == "IDAT") {
      return {png.begin() + static_cast<std::ptrdiff_t>(i + 8),
              png.begin() + static_cast<std::ptrdiff_t>(i + 8 + std::min(length, png.size() - i - 8))};
    }
    i += 12 + length;
  }
  return {};
}

// The bytes a zlib stream of stored blocks only (RFC 1950 header and Adler-32, RFC 1951 3.2.4
// blocks: a header byte, LEN, its complement, LEN bytes) carries; -1 if any block is compressed or
// the stream is malformed.
long storedBytes(const std::vector<std::uint8_t>& z) {
  long total = 0;
  std::size_t i = 2;
  for (bool last = false; !last;) {
    if (i + 5 > z.size() || ((z[i] >> 1) & 3) != 0) return -1;
    last = (z[i] & 1) != 0;
    const std::size_t len = z[i + 1] | (std::size_t{z[i + 2]} << 8);
    const std::size_t nlen = z[i + 3] | (std::size_t{z[i + 4]} << 8);
    if ((len ^ nlen) != 0xffff) return -1;
    total += static_cast<long>(len);
    i += 5 + len;
  }
  return i + 4 == z.size() ? total : -1;
}

TEST(PngEncoder, LevelZeroStoresAndHigherLevelsCompress) {
  const Image<std::uint8_t> img = picture(256, 256, 4);
  const long rows = 256 * (256 * 4 + 1);
  const std::size_t container = 8 + 25 + 13 + 12 + 12;
  const std::vector<std::uint8_t> level0 = encodePng(img.view(), 0, "x.png");
  // Every row stored unfiltered in deflate's uncompressed blocks (of at least 16 KiB: zlib's are
  // 32 KiB at libpng's settings).
  EXPECT_EQ(storedBytes(idatData(level0)), rows);
  EXPECT_LE(level0.size(), container + 2 + static_cast<std::size_t>(rows) + 5 * (rows / 16384 + 1) + 4);
  const std::vector<std::uint8_t> level1 = encodePng(img.view(), 1, "x.png");
  const std::vector<std::uint8_t> level6 = encodePng(img.view(), 6, "x.png");
  EXPECT_EQ(storedBytes(idatData(level1)), -1);
  EXPECT_LT(level1.size(), level0.size() * 2 / 3);  // the test picture has 3 bits of noise a sample
  EXPECT_LE(level6.size(), level1.size());
}

TEST(PngEncoder, TheBytesDependOnThePictureAlone) {
  const Image<std::uint8_t> big = picture(300, 200, 4);
  const Image<std::uint8_t> small = picture(20, 10, 3);
  const fs::path dir = scratch();
  for (const int level : {0, 3}) {
    const std::vector<std::uint8_t> alone = encodePng(small.view(), level, "s.png");
    // The writer keeps its buffers and compressor per thread: a big picture before must not show.
    writePngAtLevel(dir / "big.png", big.view(), level);
    writePngAtLevel(dir / "small.png", small.view(), level);
    EXPECT_EQ(slurp(dir / "small.png"), alone) << level;
    std::thread([&] { writePngAtLevel(dir / "other_thread.png", small.view(), level); }).join();
    EXPECT_EQ(slurp(dir / "other_thread.png"), alone) << level;
  }
  fs::remove_all(dir);
}

TEST(PngEncoder, OpenImageIoReadsItAsAnRgbaPng) {
  const fs::path dir = scratch();
  const Image<std::uint8_t> img = picture(64, 32, 4);
  writePngAtLevel(dir / "f.png", img.view(), 0);
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open((dir / "f.png").string(), &config);
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 4);
  std::vector<std::uint8_t> back(img.samples.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, img.samples);
  fs::remove_all(dir);
}

TEST(PngEncoder, FailuresNameTheFileAndLeaveNothing) {
  const fs::path dir = scratch();
  const Image<std::uint8_t> img = picture(8, 8, 4);
  const auto message = [&](const auto& write) {
    try {
      write();
    } catch (const ImageIoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const fs::path missing = dir / "no_such_dir" / "f.png";
  EXPECT_NE(message([&] { writePngAtLevel(missing, img.view(), 0); }).find(missing.string() + ": cannot create"),
            std::string::npos);
  EXPECT_NE(message([&] { writePngAtLevel(dir / "l.png", img.view(), 10); }).find("l.png: PNG compression level 10"),
            std::string::npos);
  EXPECT_NE(message([&] {
              writePngAtLevel(dir / "c.png", ImageView<std::uint8_t>{8, 8, 5, img.samples.data()}, 0);
            }).find("c.png: cannot write 5 channel(s)"),
            std::string::npos);
  EXPECT_NE(message([&] {
              writePngAtLevel(dir / "e.png", ImageView<std::uint8_t>{0, 8, 4, img.samples.data()}, 0);
            }).find("e.png: cannot write a 0x8 image"),
            std::string::npos);
  // An error inside libpng (a width past its limit of a million): its message, the file's name,
  // and the thread's next picture is still right.
  const std::vector<std::uint8_t> wide(1'000'001);
  EXPECT_NE(message([&] {
              writePngAtLevel(dir / "w.png", ImageView<std::uint8_t>{1'000'001, 1, 1, wide.data()}, 1);
            }).find("w.png: cannot encode the PNG: "),
            std::string::npos);
  writePngAtLevel(dir / "after.png", img.view(), 1);
  EXPECT_EQ(slurp(dir / "after.png"), encodePng(img.view(), 1, "after.png"));
  fs::remove(dir / "after.png");
  if (fs::exists("/dev/full")) {
    // A full disk: the write fails, the temporary goes, and the message names the final file.
    const fs::path full = dir / "full.png";
    fs::create_symlink("/dev/full", dir / ".full.tmp.png");
    EXPECT_NE(message([&] { writePngAtLevel(full, img.view(), 0); }).find(full.string() + ": cannot write the PNG"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(full));
  }
  EXPECT_TRUE(fs::is_empty(dir)) << fs::directory_iterator(dir)->path();
  fs::remove_all(dir);
}

// In a staged directory (a run's, replace_file.hpp) the file is written under its own name: no
// temporary beside it, the same bytes; a write that fails removes what it wrote under that name.
TEST(PngEncoder, InAStagedDirectoryTheFileIsWrittenUnderItsOwnName) {
  const fs::path dir = scratch();
  const Image<std::uint8_t> img = picture(33, 17, 4);
  for (const int level : {0, 1}) {
    const fs::path file = dir / "f.png";
    writePngAtLevel(file, img.view(), level, FileChannels::RgbOfRgba, FilePlacement::InStagedDirectory);
    EXPECT_EQ(slurp(file), encodePng(img.view(), level, "f.png", FileChannels::RgbOfRgba)) << level;
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"f.png"}) << level;
    fs::remove(file);
  }
  if (fs::exists("/dev/full")) {
    const fs::path full = dir / "full.png";
    fs::create_symlink("/dev/full", full);
    try {
      writePngAtLevel(full, img.view(), 0, FileChannels::AsGiven, FilePlacement::InStagedDirectory);
      ADD_FAILURE() << "a write to /dev/full succeeded";
    } catch (const ImageIoError& e) {
      EXPECT_NE(std::string(e.what()).find(full.string() + ": cannot write the PNG"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(fs::symlink_status(full)));
  }
  EXPECT_TRUE(fs::is_empty(dir)) << fs::directory_iterator(dir)->path();
  fs::remove_all(dir);
}

// RgbOfRgba asks for a 4-channel image.
TEST(PngEncoder, RgbOfRgbaNeedsFourChannels) {
  const Image<std::uint8_t> img = picture(4, 4, 3);
  EXPECT_THROW(encodePng(img.view(), 0, "x.png", FileChannels::RgbOfRgba), ImageIoError);
}

}  // namespace
}  // namespace vbim::imageio
