#include "imageio/texel_files.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "imageio/exr_writer.hpp"
#include "imageio/png_encoder.hpp"

namespace vbim::imageio {

namespace {

// Packs the texels' R, G and B into the first three quarters of their own bytes, in place (each
// texel's three bytes land at or before where they were read). Four texels at a time as two 64-bit
// words in and a 64-bit and a 32-bit word out, straight from registers (built in a small array and
// copied out, the words went through the stack, and reloading them stalled on store forwarding:
// most of the picture thread's time, perf, 2026-12-05); a byte at a time on a big-endian host and
// for the rest.
void dropAlphaInPlace(Rgba8Image& texels) {
  std::uint8_t* p = texels.pixels.data();
  const std::size_t count = texels.pixels.size() / 4;
  std::size_t i = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; i + 4 <= count; i += 4) {
      std::uint64_t a = 0;            // R0 G0 B0 A0 R1 G1 B1 A1, first byte lowest
      std::uint64_t b = 0;            // R2 G2 B2 A2 R3 G3 B3 A3
      std::memcpy(&a, p + i * 4, 8);  // all 16 bytes read before the 12 are written
      std::memcpy(&b, p + i * 4 + 8, 8);
      const std::uint64_t first = (a & 0xffffffu) | ((a >> 8) & 0xffffff000000u) | (b << 48);         // R0..G2
      const auto rest = static_cast<std::uint32_t>(((b >> 16) & 0xffu) | ((b >> 24) & 0xffffff00u));  // B2..B3
      std::memcpy(p + i * 3, &first, 8);
      std::memcpy(p + i * 3 + 8, &rest, 4);
    }
  }
  for (; i < count; ++i) {
    for (std::size_t c = 0; c < 3; ++c) p[i * 3 + c] = p[i * 4 + c];
  }
}

}  // namespace

void writeTexelImage(const std::filesystem::path& path, Rgba8Image& texels, const TexelFileFormat& format) {
  // Opaque pictures carry no alpha channel (RGB): the same picture to a viewer as alpha 255
  // everywhere, with a quarter less to copy, check and write (issue #31).
  const int channels = format.gsAlpha ? 4 : 3;
  if (!format.gsAlpha) dropAlphaInPlace(texels);
  const ImageView<std::uint8_t> samples{texels.width, texels.height, channels, texels.pixels.data()};
  if (format.exr) {
    std::vector<float> scaled(samples.sampleCount());  // 8-bit texels as 0..1 (alpha 0x80 = 0.502)
    for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = static_cast<float>(samples.samples[i]) / 255.0f;
    writeExr(path, ImageView<float>{texels.width, texels.height, channels, scaled.data()});
  } else {
    writePngAtLevel(path, samples, format.pngLevel);
  }
}

}  // namespace vbim::imageio
