#include "imageio/exr_writer.hpp"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <array>
#include <exception>
#include <string>
#include <vector>

#include "imageio/error.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

// OpenEXR's names for the channels of an interleaved pixel (its readers sort them by name).
const char* channelName(int channels, int c) {
  static constexpr std::array<const char*, 2> kGrey = {"Y", "A"};
  static constexpr std::array<const char*, 4> kColour = {"R", "G", "B", "A"};
  return channels <= 2 ? kGrey[static_cast<std::size_t>(c)] : kColour[static_cast<std::size_t>(c)];
}

template <typename Sample>
void writeSamples(const fs::path& target, int width, int height, int channels, Imf::PixelType type,
                  const Sample* samples) {
  Imf::Header header(width, height);
  // Both lossless. PIZ (wavelet) is OpenEXR's choice for half-float pictures (ImfRgbaFile.h's
  // default, what vbim play and decode have always written); ZIP suits 32-bit data layers.
  header.compression() = type == Imf::HALF ? Imf::PIZ_COMPRESSION : Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer frame;
  const std::size_t xStride = sizeof(Sample) * static_cast<std::size_t>(channels);
  const std::size_t yStride = xStride * static_cast<std::size_t>(width);
  for (int c = 0; c < channels; ++c) {
    header.channels().insert(channelName(channels, c), Imf::Channel(type));
    // OpenEXR only reads through the slice pointer when writing.
    char* base = reinterpret_cast<char*>(const_cast<Sample*>(samples + c));
    frame.insert(channelName(channels, c), Imf::Slice(type, base, xStride, yStride));
  }
  Imf::OutputFile file(target.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(height);
}

}  // namespace

void writeExr(const fs::path& path, ImageView<float> image, ExrSamples stored, FilePlacement placement) {
  if (image.width <= 0 || image.height <= 0) {
    throw ImageIoError(path.string() + ": cannot write a " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image (expected a positive size)");
  }
  if (image.channels < 1 || image.channels > 4) {
    throw ImageIoError(path.string() + ": cannot write " + std::to_string(image.channels) +
                       " channel(s) as OpenEXR (expected 1 to 4)");
  }
  writePlaced(path, placement, [&](const fs::path& file) {
    try {
      if (stored == ExrSamples::Float) {
        writeSamples(file, image.width, image.height, image.channels, Imf::FLOAT, image.samples);
      } else {
        const std::vector<half> halves(image.samples, image.samples + image.sampleCount());
        writeSamples(file, image.width, image.height, image.channels, Imf::HALF, halves.data());
      }
    } catch (const std::exception& e) {
      throw ImageIoError(path.string() + ": cannot write the OpenEXR file: " + e.what());
    }
  });
}

}  // namespace vbim::imageio
