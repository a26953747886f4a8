#include "runtime/image_file.hpp"

#include <png.h>

#include <OpenEXR/ImfRgbaFile.h>

#include <string>
#include <vector>

namespace vbim {
namespace {

void checkSize(const std::filesystem::path& path, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw ImageFileError(path.string() + ": cannot write a " + std::to_string(width) + "x" + std::to_string(height) +
                         " image (expected a positive size)");
  }
}

}  // namespace

void writePng(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba) {
  checkSize(path, width, height);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGBA;
  // The simplified API keeps libpng's setjmp error handling inside libpng: no longjmp through our frames.
  const int ok = png_image_write_to_file(&image, path.c_str(), 0, rgba, 0, nullptr);
  const std::string message = image.message;
  png_image_free(&image);
  if (!ok) throw ImageFileError(path.string() + ": cannot write the PNG: " + message);
}

void writeExr(const std::filesystem::path& path, int width, int height, const float* rgba) {
  checkSize(path, width, height);
  std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < pixels.size(); ++i)
    pixels[i] = Imf::Rgba(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]);
  try {
    Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_RGBA);
    file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(width));
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw ImageFileError(path.string() + ": cannot write the OpenEXR file: " + e.what());
  }
}

}  // namespace vbim
