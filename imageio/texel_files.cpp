#include "imageio/texel_files.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "imageio/exr_writer.hpp"
#include "imageio/png_encoder.hpp"
#include "imageio/rgb_pack.hpp"

namespace vbim::imageio {

void writeTexelImage(const std::filesystem::path& path, Rgba8Image& texels, const TexelFileFormat& format,
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
  const int channels = format.gsAlpha ? 4 : 3;
  if (!format.gsAlpha) packRgbOfRgba(texels.pixels.data(), texels.pixels.size() / 4, texels.pixels.data());
  const ImageView<std::uint8_t> samples{texels.width, texels.height, channels, texels.pixels.data()};
  std::vector<float> scaled(samples.sampleCount());  // 8-bit texels as 0..1 (alpha 0x80 = 0.502)
  for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = static_cast<float>(samples.samples[i]) / 255.0f;
  writeExr(path, ImageView<float>{texels.width, texels.height, channels, scaled.data()}, ExrSamples::Half, placement);
}

}  // namespace vbim::imageio
