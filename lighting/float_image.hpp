// Interleaved float images for the generator's outputs (linear, normalised irradiance or radiance)
// and its inputs (albedo). Row-major, tightly packed: index = (y * width + x) * channels + c.
#pragma once

#include <cstddef>
#include <vector>

namespace vbim::lighting {

struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;

  FloatImage() = default;
  FloatImage(int w, int h, int c)
      : width(w), height(h), channels(c), pixels(static_cast<std::size_t>(w) * h * c, 0.0f) {}
  float* at(int x, int y) { return pixels.data() + (static_cast<std::size_t>(y) * width + x) * channels; }
  const float* at(int x, int y) const { return pixels.data() + (static_cast<std::size_t>(y) * width + x) * channels; }
  bool empty() const { return width <= 0 || height <= 0; }
};

}  // namespace vbim::lighting
