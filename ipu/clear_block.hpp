// Zeroing a macroblock's 8x8 coefficient block after its inverse DCT, for the next coded block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace vbim::ipu {

// All 64 coefficients (the mismatch toggle F[7][7] included) by eight 16-byte stores, without a
// branch: a loop over the rows the masks name mispredicts its count on busy pictures, and a
// 128-byte memset became `rep stos`, whose start-up cost showed at ~3 % of a decode.
inline void clearBlock(std::int16_t* blk) {
  using Row = std::int16_t[8];
  static constexpr Row kZero{};
#pragma GCC unroll 8
  for (int r = 0; r < 8; ++r) std::memcpy(blk + std::ptrdiff_t{8} * r, kZero, sizeof kZero);
}

}  // namespace vbim::ipu
