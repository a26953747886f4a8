#include "imageio/png_writer.hpp"

#include <png.h>

#include <string>

#include "imageio/error.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

void checkShape(const fs::path& path, int width, int height, int channels, bool sixteenBit) {
  if (width <= 0 || height <= 0) {
    throw ImageIoError(path.string() + ": cannot write a " + std::to_string(width) + "x" + std::to_string(height) +
                       " image (expected a positive size)");
  }
  const bool ok = sixteenBit ? (channels == 1 || channels == 3) : (channels >= 1 && channels <= 4);
  if (!ok) {
    throw ImageIoError(path.string() + ": cannot write " + std::to_string(channels) + " channel(s) as a " +
                       (sixteenBit ? "16-bit PNG (expected 1 or 3)" : "PNG (expected 1 to 4)"));
  }
}

png_uint_32 formatOf(int channels, bool sixteenBit) {
  png_uint_32 format = 0;
  if (channels >= 3) format |= PNG_FORMAT_FLAG_COLOR;
  if (channels == 2 || channels == 4) format |= PNG_FORMAT_FLAG_ALPHA;
  if (sixteenBit) format |= PNG_FORMAT_FLAG_LINEAR;
  return format;
}

// The one place a PNG is written: both public overloads end here.
void writePngSamples(const fs::path& path, int width, int height, int channels, bool sixteenBit, const void* samples,
                     PngSpeed speed) {
  checkShape(path, width, height, channels, sixteenBit);
  writeThenRename(path, [&](const fs::path& temporary) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = formatOf(channels, sixteenBit);
    if (speed == PngSpeed::Fast) image.flags |= PNG_IMAGE_FLAG_FAST;
    // The simplified API keeps libpng's setjmp error handling inside libpng: no longjmp through our frames.
    const int ok = png_image_write_to_file(&image, temporary.c_str(), 0, samples, 0, nullptr);
    const std::string message = image.message;
    png_image_free(&image);
    if (!ok) throw ImageIoError(path.string() + ": cannot write the PNG: " + message);
  });
}

}  // namespace

void writePng(const fs::path& path, ImageView<std::uint8_t> image, PngSpeed speed) {
  writePngSamples(path, image.width, image.height, image.channels, false, image.samples, speed);
}

void writePng(const fs::path& path, ImageView<std::uint16_t> image, PngSpeed speed) {
  writePngSamples(path, image.width, image.height, image.channels, true, image.samples, speed);
}

}  // namespace vbim::imageio
