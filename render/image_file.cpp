#include "render/image_file.hpp"

#include <memory>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "render/render_error.hpp"

namespace vbim::render {

Rgba8Image readRgba8(const std::filesystem::path& path) {
  // The colour channels as stored: OpenImageIO would otherwise multiply them by alpha (the play
  // frames carry the GS alpha 0x80, about one half).
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw RenderError(path.string() + ": cannot open the image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3 || spec.width <= 0 || spec.height <= 0) {
    throw RenderError(path.string() + ": expected an RGB image, found " + std::to_string(spec.nchannels) +
                      " channel(s)");
  }
  std::vector<std::uint8_t> data(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, data.data())) {
    throw RenderError(path.string() + ": cannot read the image: " + in->geterror());
  }
  Rgba8Image img(spec.width, spec.height);
  for (std::size_t i = 0; i < static_cast<std::size_t>(spec.width) * spec.height; ++i) {
    for (int c = 0; c < 3; ++c) img.pixels[i * 4 + c] = data[i * spec.nchannels + c];
    img.pixels[i * 4 + 3] = 0x80;
  }
  return img;
}

void writePng(const std::filesystem::path& path, const Rgba8Image& image) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw RenderError(path.string() + ": cannot create the image writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  // Level 6 costs 2-3x the time for a few % (docs/dependencies.md#png-compression-level).
  spec.attribute("png:compressionLevel", 3);
  // Strides skip the alpha byte.
  if (!out->open(path.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data(), 4, static_cast<OIIO::stride_t>(image.width) * 4) ||
      !out->close()) {
    throw RenderError(path.string() + ": cannot write the image: " + out->geterror());
  }
}

}  // namespace vbim::render
