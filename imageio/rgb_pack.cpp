#include "imageio/rgb_pack.hpp"

#include <bit>
#include <cstring>

namespace vbim::imageio {

// Four texels at a time as two 64-bit words in and a 64-bit and a 32-bit word out, straight from
// registers (built in a small array and copied out, the words went through the stack, and
// reloading them stalled on store forwarding: most of the picture thread's time, perf,
// 2026-12-05). All 16 bytes are read before the 12 are written, and the 12 land at or before the
// next texels' bytes, so the same code packs in place. A byte at a time on a big-endian host and
// for the rest.
void packRgbOfRgba(const std::uint8_t* rgba, std::size_t texels, std::uint8_t* rgb) {
  std::size_t i = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; i + 4 <= texels; i += 4) {
      std::uint64_t a = 0;  // R0 G0 B0 A0 R1 G1 B1 A1, first byte lowest
      std::uint64_t b = 0;  // R2 G2 B2 A2 R3 G3 B3 A3
      std::memcpy(&a, rgba + i * 4, 8);
      std::memcpy(&b, rgba + i * 4 + 8, 8);
      const std::uint64_t first = (a & 0xffffffu) | ((a >> 8) & 0xffffff000000u) | (b << 48);         // R0..G2
      const auto rest = static_cast<std::uint32_t>(((b >> 16) & 0xffu) | ((b >> 24) & 0xffffff00u));  // B2..B3
      std::memcpy(rgb + i * 3, &first, 8);
      std::memcpy(rgb + i * 3 + 8, &rest, 4);
    }
  }
  packRgbOfRgbaReference(rgba + i * 4, texels - i, rgb + i * 3);
}

void packRgbOfRgbaReference(const std::uint8_t* rgba, std::size_t texels, std::uint8_t* rgb) {
  for (std::size_t i = 0; i < texels; ++i) {
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
  }
}

}  // namespace vbim::imageio
