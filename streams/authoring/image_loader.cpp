#include "streams/authoring/image_loader.hpp"

#include <OpenImageIO/imageio.h>

#include "streams/authoring/authoring_error.hpp"

namespace vbim::streams {

LoadedImage loadImage(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    std::string why = OIIO::geterror();
    if (why.empty()) why = "not an image OpenImageIO can read";
    throw AuthoringError(path.string() + ": cannot read the image: " + why);
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw AuthoringError(path.string() + ": image has no pixels");
  const int nch = spec.nchannels;
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * nch);
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, px.data()))
    throw AuthoringError(path.string() + ": cannot decode the image: " + in->geterror());
  LoadedImage out;
  const auto base = spec.format.basetype;
  out.floatingPoint = base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::DOUBLE;
  out.rgb = FloatRgbImage(spec.width, spec.height);
  const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) out.rgb.rgb[i * 3 + c] = px[i * nch + (nch >= 3 ? c : 0)];
  return out;
}

Rgba8Image loadFrame(const std::filesystem::path& path, InputEncoding enc, const ToneMapping& m) {
  LoadedImage img = loadImage(path);
  const bool linear = enc == InputEncoding::Linear || (enc == InputEncoding::Auto && img.floatingPoint);
  return linear ? toneMap(img.rgb, m) : quantiseEncoded(img.rgb);
}

}  // namespace vbim::streams
