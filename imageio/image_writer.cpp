#include "imageio/image_writer.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "imageio/error.hpp"
#include "imageio/exr_writer.hpp"
#include "imageio/png_writer.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

std::string extensionOf(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

[[noreturn]] void refuse(const fs::path& path, const char* samples, const char* expected) {
  throw ImageIoError(path.string() + ": cannot write " + samples + " samples to this format (" + expected + ")");
}

// The formats the project has no writer of its own for (TIFF, JPEG, ...).
template <typename T>
void writeWithOpenImageIo(const fs::path& path, ImageView<T> image, OIIO::TypeDesc type) {
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0) {
    throw ImageIoError(path.string() + ": cannot write a " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image of " + std::to_string(image.channels) +
                       " channel(s) (expected a positive size)");
  }
  writeThenRename(path, [&](const fs::path& temporary) {
    auto out = OIIO::ImageOutput::create(temporary.string());
    if (!out) throw ImageIoError(path.string() + ": no image writer for this extension: " + OIIO::geterror());
    const OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
    if (!out->open(temporary.string(), spec) || !out->write_image(type, image.samples) || !out->close()) {
      throw ImageIoError(path.string() + ": cannot write the image: " + out->geterror());
    }
  });
}

}  // namespace

void writeImage(const fs::path& path, ImageView<std::uint8_t> image) {
  const std::string ext = extensionOf(path);
  if (ext == ".png") return writePng(path, image);
  if (ext == ".exr") refuse(path, "8-bit", "OpenEXR holds floats");
  writeWithOpenImageIo(path, image, OIIO::TypeDesc::UINT8);
}

void writeImage(const fs::path& path, ImageView<std::uint16_t> image) {
  const std::string ext = extensionOf(path);
  if (ext == ".png") return writePng(path, image);
  if (ext == ".exr") refuse(path, "16-bit", "OpenEXR holds floats");
  writeWithOpenImageIo(path, image, OIIO::TypeDesc::UINT16);
}

void writeImage(const fs::path& path, ImageView<float> image) {
  const std::string ext = extensionOf(path);
  if (ext == ".exr") return writeExr(path, image, ExrSamples::Float);
  if (ext == ".png") refuse(path, "float", "PNG holds 8- or 16-bit integers");
  writeWithOpenImageIo(path, image, OIIO::TypeDesc::FLOAT);
}

}  // namespace vbim::imageio
