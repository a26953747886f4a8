// A run's pictures (imageio/texel_files.hpp): opaque ones are RGB files with the texels' colours
// (the alpha channel dropped in place, issue #31), --alpha gs ones RGBA with the texels as they are,
// for picture sizes that exercise the four-texel packing and its tail.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "imageio/texel_files.hpp"
#include "runtime/image.hpp"

namespace vbim::imageio {
namespace {

namespace fs = std::filesystem;

Rgba8Image texels(int w, int h) {
  Rgba8Image img(w, h);
  std::uint32_t noise = 777;
  for (std::uint8_t& b : img.pixels) {
    noise = noise * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(noise >> 24);
  }
  return img;
}

// The file's samples as libpng reads them, in the layout it holds; `channels` from its header.
std::vector<std::uint8_t> readBack(const fs::path& path, int& channels) {
  png_image im{};
  im.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&im, path.c_str()) == 0) return {};
  channels = static_cast<int>(PNG_IMAGE_SAMPLE_CHANNELS(im.format));
  im.format = channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  std::vector<std::uint8_t> out(PNG_IMAGE_SIZE(im));
  if (png_image_finish_read(&im, nullptr, out.data(), 0, nullptr) == 0) return {};
  return out;
}

TEST(TexelFiles, OpaquePicturesAreRgbAndGsAlphaOnesRgba) {
  const fs::path dir = fs::temp_directory_path() / ("vbim_texel_files_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {2, 1}, {3, 1}, {5, 3}, {7, 7}, {256, 256}}) {
    const Rgba8Image original = texels(w, h);
    std::vector<std::uint8_t> rgb;
    for (std::size_t i = 0; i < original.pixels.size(); ++i) {
      if (i % 4 != 3) rgb.push_back(original.pixels[i]);
    }
    for (const int level : {0, 1}) {
      Rgba8Image copy = original;
      writeTexelImage(dir / "opaque.png", copy, TexelFileFormat{false, false, level});
      int channels = 0;
      EXPECT_EQ(readBack(dir / "opaque.png", channels), rgb) << w << "x" << h << " level " << level;
      EXPECT_EQ(channels, 3);
      copy = original;
      writeTexelImage(dir / "gs.png", copy, TexelFileFormat{false, true, level});
      EXPECT_EQ(readBack(dir / "gs.png", channels), original.pixels) << w << "x" << h << " level " << level;
      EXPECT_EQ(channels, 4);
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::imageio
