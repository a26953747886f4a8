#include "lighting/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "lighting/errors.hpp"

namespace vbim::lighting {

namespace {

namespace OIIO = OIIO_NAMESPACE;

struct Opened {
  std::unique_ptr<OIIO::ImageInput> in;
  OIIO::ImageSpec spec;
};

Opened open(const std::string& path, const char* what) {
  Opened o;
  o.in = OIIO::ImageInput::open(path);
  if (!o.in) throw LightingError(path + ": cannot read the " + what + ": " + OIIO::geterror());
  o.spec = o.in->spec();
  if (o.spec.width <= 0 || o.spec.height <= 0) {
    throw LightingError(path + ": the " + what + " is empty (" + std::to_string(o.spec.width) + "x" +
                        std::to_string(o.spec.height) + ")");
  }
  if (o.spec.depth > 1) throw LightingError(path + ": the " + what + " is a volume; expected a 2-D image");
  return o;
}

template <typename T>
std::vector<T> readAll(Opened& o, OIIO::TypeDesc type, const std::string& path) {
  std::vector<T> data(static_cast<std::size_t>(o.spec.width) * o.spec.height * o.spec.nchannels);
  if (!o.in->read_image(0, 0, 0, o.spec.nchannels, type, data.data())) {
    throw LightingError(path + ": cannot decode the image: " + o.in->geterror());
  }
  return data;
}

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : static_cast<float>(std::pow((v + 0.055) / 1.055, 2.4));
}

void writeWith(const std::string& path, int width, int height, int channels, OIIO::TypeDesc fileType,
               OIIO::TypeDesc dataType, const void* data) {
  namespace fs = std::filesystem;
  const fs::path final(path);
  // Keep the extension so the writer is chosen from it.
  const fs::path tmp = final.parent_path() / ("." + final.stem().string() + ".tmp" + final.extension().string());
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw LightingError(path + ": no image writer for this extension: " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, channels, fileType);
  if (!out->open(tmp.string(), spec) || !out->write_image(dataType, data) || !out->close()) {
    const std::string err = out->geterror();
    std::error_code ec;
    fs::remove(tmp, ec);
    throw LightingError(path + ": cannot write the image: " + err);
  }
  std::error_code ec;
  fs::rename(tmp, final, ec);
  if (ec) throw LightingError(path + ": cannot move the finished image into place: " + ec.message());
}

}  // namespace

Terrain readHeightfield(const std::string& path, double cellSize, double verticalScale) {
  Opened o = open(path, "heightfield");
  if (o.spec.nchannels != 1) {
    throw LightingError(path + ": the heightfield has " + std::to_string(o.spec.nchannels) +
                        " channels; expected a single-channel (greyscale) image");
  }
  if (!(verticalScale > 0) || !std::isfinite(verticalScale)) {
    throw LightingError(path + ": vertical scale must be a positive number of metres");
  }
  const OIIO::TypeDesc f = o.spec.format;
  if (f == OIIO::TypeDesc::UINT8 || f == OIIO::TypeDesc::UINT16) {
    const bool wide = f == OIIO::TypeDesc::UINT16;
    std::vector<std::uint32_t> counts;
    if (wide) {
      const auto raw = readAll<std::uint16_t>(o, OIIO::TypeDesc::UINT16, path);
      counts.assign(raw.begin(), raw.end());
    } else {
      const auto raw = readAll<std::uint8_t>(o, OIIO::TypeDesc::UINT8, path);
      counts.assign(raw.begin(), raw.end());
    }
    return terrainFromCounts(o.spec.width, o.spec.height, counts, cellSize, verticalScale / (wide ? 65535.0 : 255.0),
                             path);
  }
  auto values = readAll<float>(o, OIIO::TypeDesc::FLOAT, path);
  for (float& v : values) v = static_cast<float>(v * verticalScale);
  return terrainFromMetres(o.spec.width, o.spec.height, values, cellSize, path);
}

FloatImage readColourMap(const std::string& path) {
  Opened o = open(path, "colour map");
  const int ch = o.spec.nchannels;
  if (ch != 1 && ch != 3 && ch != 4) {
    throw LightingError(path + ": the colour map has " + std::to_string(ch) + " channels; expected 1, 3 or 4");
  }
  const bool encoded = !o.spec.format.is_floating_point();
  const auto raw = readAll<float>(o, OIIO::TypeDesc::FLOAT, path);
  FloatImage img(o.spec.width, o.spec.height, 3);
  const std::size_t n = static_cast<std::size_t>(o.spec.width) * o.spec.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = raw[i * ch + (ch == 1 ? 0 : c)];
      img.pixels[i * 3 + c] = encoded ? srgbToLinear(v) : v;
    }
  }
  return img;
}

FloatImage readDensityMap(const std::string& path) {
  Opened o = open(path, "cloud texture");
  if (o.spec.nchannels != 1) {
    throw LightingError(path + ": the cloud texture has " + std::to_string(o.spec.nchannels) +
                        " channels; expected a single-channel image");
  }
  FloatImage img(o.spec.width, o.spec.height, 1);
  img.pixels = readAll<float>(o, OIIO::TypeDesc::FLOAT, path);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    if (!std::isfinite(img.pixels[i])) {
      throw LightingError(path + ": value at pixel (" + std::to_string(i % img.width) + ", " +
                          std::to_string(i / img.width) + ") is not finite");
    }
    img.pixels[i] = std::clamp(img.pixels[i], 0.0f, 1.0f);
  }
  return img;
}

void writeImage(const std::string& path, const FloatImage& image) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".exr") {
    writeWith(path, image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT,
              image.pixels.data());
    return;
  }
  std::vector<std::uint8_t> bytes(image.pixels.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = static_cast<std::uint8_t>(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  writeWith(path, image.width, image.height, image.channels, OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT8,
            bytes.data());
}

void writeGray16(const std::string& path, int width, int height, const std::vector<std::uint16_t>& pixels) {
  writeWith(path, width, height, 1, OIIO::TypeDesc::UINT16, OIIO::TypeDesc::UINT16, pixels.data());
}

}  // namespace vbim::lighting
