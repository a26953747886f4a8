#include "lighting/image_files.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "imageio/image_reader.hpp"
#include "imageio/image_writer.hpp"
#include "lighting/error.hpp"

namespace vbim::lighting {

using imageio::Image;
using imageio::ImageInfo;
using imageio::ImageReader;
using imageio::ImageView;
using imageio::SampleType;

namespace {

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : static_cast<float>(std::pow((v + 0.055) / 1.055, 2.4));
}

template <typename T>
std::vector<std::uint32_t> widen(const std::vector<T>& samples) {
  return {samples.begin(), samples.end()};
}

}  // namespace

Terrain readHeightfield(const std::string& path, double cellSize, double verticalScale) {
  ImageReader in(path, "heightfield");
  const ImageInfo& info = in.info();
  if (info.channels != 1) {
    throw in.error("has " + std::to_string(info.channels) + " channels; expected a single-channel (greyscale) image");
  }
  if (!(verticalScale > 0) || !std::isfinite(verticalScale)) {
    throw LightingError(path + ": vertical scale must be a positive number of metres");
  }
  if (info.stored == SampleType::UInt8) {
    return terrainFromCounts(info.width, info.height, widen(in.readUInt8().samples), cellSize, verticalScale / 255.0,
                             path);
  }
  if (info.stored == SampleType::UInt16) {
    return terrainFromCounts(info.width, info.height, widen(in.readUInt16().samples), cellSize, verticalScale / 65535.0,
                             path);
  }
  std::vector<float> metres = in.readFloat().samples;
  for (float& v : metres) v = static_cast<float>(v * verticalScale);
  return terrainFromMetres(info.width, info.height, metres, cellSize, path);
}

bool heightfieldHasFloatSamples(const std::string& path) {
  const ImageReader in(path, "heightfield");
  return in.info().stored != SampleType::UInt8 && in.info().stored != SampleType::UInt16;
}

FloatImage readColourMap(const std::string& path) {
  ImageReader in(path, "colour map");
  const int channels = in.info().channels;
  if (channels != 1 && channels != 3 && channels != 4) {
    throw in.error("has " + std::to_string(channels) + " channels; expected 1, 3 or 4");
  }
  const bool encoded = !in.info().floatingPoint;
  const Image<float> raw = in.readFloat();
  FloatImage image(raw.width, raw.height, 3);
  const std::size_t pixels = static_cast<std::size_t>(raw.width) * static_cast<std::size_t>(raw.height);
  const auto ch = static_cast<std::size_t>(channels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = raw.samples[i * ch + (ch == 1 ? 0 : c)];
      image.pixels[i * 3 + c] = encoded ? srgbToLinear(v) : v;
    }
  }
  return image;
}

FloatImage readDensityMap(const std::string& path) {
  ImageReader in(path, "cloud texture");
  if (in.info().channels != 1) {
    throw in.error("has " + std::to_string(in.info().channels) + " channels; expected a single-channel image");
  }
  Image<float> raw = in.readFloat();
  FloatImage image(raw.width, raw.height, 1);
  image.pixels = std::move(raw.samples);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!std::isfinite(image.pixels[i])) {
      throw LightingError(path + ": value at pixel (" + std::to_string(i % image.width) + ", " +
                          std::to_string(i / image.width) + ") is not finite");
    }
    image.pixels[i] = std::clamp(image.pixels[i], 0.0f, 1.0f);
  }
  return image;
}

void writeImage(const std::filesystem::path& path, const FloatImage& image) {
  const ImageView<float> floats{image.width, image.height, image.channels, image.pixels.data()};
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".exr") {
    imageio::writeImage(path, floats);
    return;
  }
  Image<std::uint8_t> bytes(image.width, image.height, image.channels);
  for (std::size_t i = 0; i < bytes.samples.size(); ++i) {
    // Float "+ 0.5, truncate" (not lround) keeps the 8-bit files' values as they have always been.
    // NOLINTNEXTLINE(bugprone-incorrect-roundings)
    bytes.samples[i] = static_cast<std::uint8_t>(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  imageio::writeImage(path, bytes.view());
}

}  // namespace vbim::lighting
