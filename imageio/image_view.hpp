// The pixels imageio reads and writes: interleaved samples, row-major, top row first, tightly packed
// (a row is width * channels samples). A view borrows the samples of a caller's buffer (a
// Rgba8Image, a lighting::FloatImage, ...); an Image owns them.
#pragma once

#include <cstddef>
#include <vector>

namespace vbim::imageio {

template <typename T>
struct ImageView {
  int width = 0;
  int height = 0;
  int channels = 0;
  const T* samples = nullptr;  // width * height * channels

  std::size_t sampleCount() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels);
  }
};

// Which samples of an 8-bit image a writer puts in the file: all of them as they are, or the first
// three of each 4-channel pixel (RGB of RGBA), packed as the file's rows are written: one pass over
// the pixels, no packed copy of them (issue #31: vbim play's opaque frames).
enum class FileChannels { AsGiven, RgbOfRgba };

template <typename T>
struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<T> samples;

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), samples(static_cast<std::size_t>(w) * h * c, T{}) {}
  ImageView<T> view() const { return {width, height, channels, samples.data()}; }
};

}  // namespace vbim::imageio
