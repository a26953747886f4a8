// libpng's reading of a PNG in memory (its simplified API), in the channel layout it was written
// with: the reference the imageio writer tests decode their files with.
#pragma once

#include <png.h>

#include <cstdint>
#include <vector>

namespace vbim::imageio::testing {

// The samples of `png` as `channels` (1 to 4) channels per pixel; empty if libpng refuses the bytes.
// `width` and `height`, when given, receive the picture's size.
inline std::vector<std::uint8_t> decodeWithLibpng(const std::vector<std::uint8_t>& png, int channels,
                                                  int* width = nullptr, int* height = nullptr) {
  png_image im{};
  im.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_memory(&im, png.data(), png.size()) == 0) return {};
  static const png_uint_32 kFormat[] = {0, PNG_FORMAT_GRAY, PNG_FORMAT_GA, PNG_FORMAT_RGB, PNG_FORMAT_RGBA};
  im.format = kFormat[channels];
  std::vector<std::uint8_t> out(PNG_IMAGE_SIZE(im));
  if (png_image_finish_read(&im, nullptr, out.data(), 0, nullptr) == 0) return {};
  if (width != nullptr) *width = static_cast<int>(im.width);
  if (height != nullptr) *height = static_cast<int>(im.height);
  return out;
}

}  // namespace vbim::imageio::testing
