#include "imageio/image_reader.hpp"

#include <OpenImageIO/imageio.h>

#include <utility>

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

SampleType sampleTypeOf(const OIIO::TypeDesc& format) {
  switch (format.basetype) {
    case OIIO::TypeDesc::UINT8:
      return SampleType::UInt8;
    case OIIO::TypeDesc::UINT16:
      return SampleType::UInt16;
    case OIIO::TypeDesc::HALF:
      return SampleType::Half;
    case OIIO::TypeDesc::FLOAT:
      return SampleType::Float;
    default:
      return SampleType::Other;
  }
}

}  // namespace

struct ImageReader::Impl {
  std::string path;
  std::string what;
  std::unique_ptr<OIIO::ImageInput> in;
  ImageInfo info;

  template <typename T>
  Image<T> read(OIIO::TypeDesc type) {
    Image<T> image(info.width, info.height, info.channels);
    if (!in->read_image(0, 0, 0, info.channels, type, image.samples.data())) {
      throw ImageIoError(path + ": cannot decode the " + what + ": " + in->geterror());
    }
    return image;
  }
};

ImageReader::ImageReader(const fs::path& path, std::string what, AlphaMode alpha) : impl_(std::make_unique<Impl>()) {
  impl_->path = path.string();
  impl_->what = std::move(what);
  OIIO::ImageSpec config;
  if (alpha == AlphaMode::AsStored) config.attribute("oiio:UnassociatedAlpha", 1);
  impl_->in = OIIO::ImageInput::open(impl_->path, &config);
  if (!impl_->in) {
    std::string why = OIIO::geterror();
    if (why.empty()) why = "not a picture OpenImageIO can read";
    throw ImageIoError(impl_->path + ": cannot read the " + impl_->what + ": " + why);
  }
  const OIIO::ImageSpec& spec = impl_->in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw error("is empty (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) + ", " +
                std::to_string(spec.nchannels) + " channels)");
  }
  if (spec.depth > 1) throw error("is a volume; expected a 2-D image");
  // A damaged or hostile header can claim any size; refuse before allocating for it.
  const auto samples = static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height) *
                       static_cast<std::uint64_t>(spec.nchannels);
  if (samples > kMaxImageSamples) {
    throw error("is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " with " +
                std::to_string(spec.nchannels) + " channels, more than the " + std::to_string(kMaxImageSamples) +
                " samples vbim reads from one picture");
  }
  impl_->info = {spec.width, spec.height, spec.nchannels, sampleTypeOf(spec.format), spec.format.is_floating_point()};
}

ImageReader::~ImageReader() = default;

const ImageInfo& ImageReader::info() const {
  return impl_->info;
}

Image<std::uint8_t> ImageReader::readUInt8() {
  return impl_->read<std::uint8_t>(OIIO::TypeDesc::UINT8);
}
Image<std::uint16_t> ImageReader::readUInt16() {
  return impl_->read<std::uint16_t>(OIIO::TypeDesc::UINT16);
}
Image<float> ImageReader::readFloat() {
  return impl_->read<float>(OIIO::TypeDesc::FLOAT);
}

ImageIoError ImageReader::error(const std::string& problem) const {
  return ImageIoError(impl_->path + ": the " + impl_->what + " " + problem);
}

Rgba8Image readRgba8(const fs::path& path) {
  // The colours as stored: vbim play's frames carry the GS alpha 0x80 (about one half), which must
  // not darken them.
  ImageReader in(path, "image", AlphaMode::AsStored);
  const ImageInfo& info = in.info();
  if (info.channels < 3) {
    throw in.error("has " + std::to_string(info.channels) + " channel(s); expected an RGB or RGBA image");
  }
  const Image<std::uint8_t> samples = in.readUInt8();
  Rgba8Image image(info.width, info.height);
  const std::size_t pixels = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
  const auto channels = static_cast<std::size_t>(info.channels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) image.pixels[i * 4 + c] = samples.samples[i * channels + c];
    image.pixels[i * 4 + 3] = 0x80;
  }
  return image;
}

FloatRgbFrame readFloatRgb(const fs::path& path) {
  ImageReader in(path, "image");
  const ImageInfo& info = in.info();
  const Image<float> samples = in.readFloat();
  FloatRgbFrame frame;
  frame.floatingPoint = info.floatingPoint;
  frame.rgb = Image<float>(info.width, info.height, 3);
  const std::size_t pixels = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
  const auto channels = static_cast<std::size_t>(info.channels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      frame.rgb.samples[i * 3 + c] = samples.samples[i * channels + (channels >= 3 ? c : 0)];
    }
  }
  return frame;
}

}  // namespace vbim::imageio
