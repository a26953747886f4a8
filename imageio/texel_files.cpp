#include "imageio/texel_files.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "imageio/exr_writer.hpp"
#include "imageio/png_encoder.hpp"
#include "imageio/rgba8.hpp"

namespace vbim::imageio {

namespace {

// The alpha byte (the fourth in memory) of a texel read as a 32-bit word on this host.
constexpr std::uint32_t kAlphaMask =
    std::endian::native == std::endian::little ? std::uint32_t{0xff000000} : std::uint32_t{0x000000ff};

}  // namespace

void writeTexelImage(const std::filesystem::path& path, Rgba8Image& texels, const TexelFileFormat& format) {
  if (!format.gsAlpha) {
    // A texel at a time as one 32-bit word, which the compiler vectorises (byte by byte it did not).
    constexpr std::size_t kTexel = 4;
    std::uint8_t* p = texels.pixels.data();
    for (std::size_t i = 0; i + kTexel <= texels.pixels.size(); i += kTexel) {
      std::uint32_t t = 0;
      std::memcpy(&t, p + i, kTexel);
      t |= kAlphaMask;
      std::memcpy(p + i, &t, kTexel);
    }
  }
  if (format.exr) {
    std::vector<float> scaled(texels.pixels.size());  // 8-bit texels as 0..1 (alpha 0x80 = 0.502)
    for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = static_cast<float>(texels.pixels[i]) / 255.0f;
    writeExr(path, ImageView<float>{texels.width, texels.height, 4, scaled.data()});
  } else {
    writePngAtLevel(path, rgbaView(texels), format.pngLevel);
  }
}

}  // namespace vbim::imageio
