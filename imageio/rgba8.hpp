// The pipeline's 8-bit pictures (Rgba8Image, runtime/image.hpp) as imageio pixels.
#pragma once

#include <cstddef>
#include <cstdint>

#include "imageio/image_view.hpp"
#include "runtime/image.hpp"

namespace vbim::imageio {

// All four channels as stored (the GS's alpha: 0x80 = 1.0).
inline ImageView<std::uint8_t> rgbaView(const Rgba8Image& image) {
  return {image.width, image.height, 4, image.pixels.data()};
}

// R, G and B only, for pictures whose alpha means nothing outside the GS (rendered frames).
inline Image<std::uint8_t> rgbOf(const Rgba8Image& image) {
  Image<std::uint8_t> rgb(image.width, image.height, 3);
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  for (std::size_t i = 0; i < pixels; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb.samples[i * 3 + c] = image.pixels[i * 4 + c];
  return rgb;
}

}  // namespace vbim::imageio
