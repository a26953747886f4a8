#include "imageio/texel_files.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "imageio/exr_writer.hpp"
#include "imageio/png_encoder.hpp"

namespace vbim::imageio {

void writeTexelImage(const std::filesystem::path& path, const Rgba8Image& texels, const TexelFileFormat& format,
                     FilePlacement placement) {
  // Opaque pictures carry no alpha channel (RGB): the same picture to a viewer as alpha 255
  // everywhere, with a quarter less to copy, check and write (issue #31).
  const ImageView<std::uint8_t> rgba{texels.width, texels.height, 4, texels.pixels.data()};
  if (!format.exr) {
    // The PNG writer packs the RGB as it writes the rows (one pass over the texels).
    writePngAtLevel(path, rgba, format.pngLevel, format.gsAlpha ? FileChannels::AsGiven : FileChannels::RgbOfRgba,
                    placement);
    return;
  }
  // 8-bit texels as 0..1 (alpha 0x80 = 0.502), alpha left out of opaque pictures.
  const std::size_t channels = format.gsAlpha ? 4 : 3;
  const std::size_t count = texels.pixels.size() / 4;
  std::vector<float> scaled(count * channels);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < channels; ++c) scaled[i * channels + c] = texels.pixels[i * 4 + c] / 255.0f;
  }
  writeExr(path, ImageView<float>{texels.width, texels.height, static_cast<int>(channels), scaled.data()},
           ExrSamples::Half, placement);
}

}  // namespace vbim::imageio
