// Reading pictures of any format OpenImageIO knows (PNG, OpenEXR, TIFF, HDR, JPEG, ...): the only
// picture reader of the project. Part of the full imageio library (vbim_imageio_full), which the
// lean `vbim` program does not link.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "imageio/error.hpp"
#include "imageio/image_view.hpp"
#include "runtime/image.hpp"

namespace vbim::imageio {

// The most samples (width x height x channels) one picture may hold: 2^28, a 16384x16384 grey
// heightfield, or 1 GiB once read as floats. Larger headers are refused before any allocation.
inline constexpr std::uint64_t kMaxImageSamples = std::uint64_t{1} << 28;

enum class SampleType { UInt8, UInt16, Half, Float, Other };

// What a file holds.
struct ImageInfo {
  int width = 0;
  int height = 0;
  int channels = 0;
  SampleType stored = SampleType::Other;
  bool floatingPoint = false;  // half, float or double samples (linear light by convention)
};

// How colours come out of a file with an alpha channel. Premultiplied is OpenImageIO's default
// (colours of formats that store them unassociated, like PNG, are multiplied by alpha);
// AsStored returns them untouched.
enum class AlphaMode { Premultiplied, AsStored };

// One open picture file: look at info(), then read its samples in the type the caller needs.
class ImageReader {
 public:
  // `what` names the picture in messages ("heightfield", "colour map", "image"). Throws
  // ImageIoError "<path>: cannot read the <what>: <why>" when the file cannot be opened, and
  // "<path>: the <what> is ..." when it is empty or a volume.
  ImageReader(const std::filesystem::path& path, std::string what, AlphaMode alpha = AlphaMode::Premultiplied);
  ~ImageReader();
  ImageReader(const ImageReader&) = delete;
  ImageReader& operator=(const ImageReader&) = delete;

  const ImageInfo& info() const;

  // Every channel, converted: integer samples rescale to the full range of the type asked for
  // (8-bit 255 -> 65535 -> 1.0f), float samples are 1.0 = full scale. Reading an integer file as
  // its own type gives the stored counts exactly. Throws ImageIoError when the file cannot be decoded.
  Image<std::uint8_t> readUInt8();
  Image<std::uint16_t> readUInt16();
  Image<float> readFloat();

  // The error for a file that is readable but not what the caller expected:
  // "<path>: the <what> <problem>".
  ImageIoError error(const std::string& problem) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A colour picture as the pipeline's 8-bit RGBA (vbim play's frames, or any RGB(A) file): colours
// as stored (never multiplied by the file's alpha), alpha set to 0x80 (the GS's 1.0). Throws
// ImageIoError naming the file.
Rgba8Image readRgba8(const std::filesystem::path& path);

// A frame for authoring: three channels of floats (integer files scaled to 0..1), grey repeated into
// R, G and B, channels after the third ignored.
struct FloatRgbFrame {
  Image<float> rgb;
  bool floatingPoint = false;  // the file stored floats (taken as linear light by default)
};
FloatRgbFrame readFloatRgb(const std::filesystem::path& path);

}  // namespace vbim::imageio
