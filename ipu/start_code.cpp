#include "ipu/start_code.hpp"

#include <bit>
#include <cstring>

namespace vbim::ipu {

// Coded data holds a 0x01 byte every ~40 bytes but few pairs of zero bytes, so 14 bytes at a time
// are tested for a zero pair (a SWAR test: no branch per byte, no library call per 0x01 byte; a
// memchr for each 0x01 byte cost 5 % of the whole decode) and only a pair is looked at.
std::size_t findStartCode(const std::uint8_t* d, std::size_t n, std::size_t from) {
  constexpr std::uint64_t k7F = 0x7F7F7F7F7F7F7F7Full;
  // A zero byte whose successor in memory is zero too, among bytes 0..6 of the word at p.
  auto zeroPairs = [](const std::uint8_t* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    const std::uint64_t zero = ~(((v & k7F) + k7F) | v | k7F);  // 0x80 in each zero byte
    return std::endian::native == std::endian::little ? zero & (zero >> 8) : zero & (zero << 8);
  };
  std::size_t i = from;
  // Words at i and i + 7: pairs starting at i .. i + 13, and the byte after each (up to i + 15).
  while (i + 16 <= n) {
    if ((zeroPairs(d + i) | zeroPairs(d + i + 7)) != 0) {
      for (std::size_t k = 0; k < 14; ++k)
        if (d[i + k] == 0 && d[i + k + 1] == 0 && d[i + k + 2] == 1) return i + k;
    }
    i += 14;
  }
  for (; i + 2 < n; ++i)
    if (d[i] == 0 && d[i + 1] == 0 && d[i + 2] == 1) return i;
  return n;
}

}  // namespace vbim::ipu
