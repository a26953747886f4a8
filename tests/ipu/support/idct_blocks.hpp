// Test blocks for the inverse DCTs: sparse, dense and extreme coefficient blocks with the row and
// column masks the slice decoder would give them, shared by the IDCT and SIMD tests.
#pragma once

#include <cmath>
#include <cstdint>

#include "ipu/kernels.hpp"

namespace vbim::ipu::testing {

struct Lcg {
  std::uint32_t s;
  int below(int n) {
    s = s * 1664525u + 1013904223u;
    return static_cast<int>((s >> 8) % static_cast<std::uint32_t>(n));
  }
};

struct IdctBlock {
  std::int16_t c[64] = {};
  unsigned rows = 1;  // as the slice decoder sets them: bit 0 always, kIdctToggleOnly, kIdctFirstOnly
  unsigned cols = 1;
};

// Block t of a sequence cycling through the kinds of input: 0 dense in the full range, 1 sparse in
// the full range, 2 sparse small, 3 sparse saturated extremes, 4 DC only, 5 dense extremes with the
// signs of one output's basis (the largest sums), 6 dense small (up to +-64: natural-looking texture).
// Every third block (except DC only) gets the mismatch toggle alone in row 7 and column 7; DC-only
// blocks get it every other time, flagged kIdctFirstOnly.
inline IdctBlock makeIdctBlock(int t, Lcg& rng) {
  IdctBlock b;
  const int kind = t % 7;
  auto put = [&](int pos, int v) {
    b.c[pos] = static_cast<std::int16_t>(v);
    b.rows |= 1u << (pos >> 3);
    b.cols |= 1u << (pos & 7);
  };
  if (kind == 4) {
    b.c[0] = static_cast<std::int16_t>(rng.below(4096) - 2048);
    b.rows |= kIdctFirstOnly;
    if (rng.below(2)) {
      b.c[63] = static_cast<std::int16_t>(rng.below(2) ? 1 : -1);
      b.rows |= kIdctToggleOnly;
    }
    return b;
  }
  if (kind == 5) {
    const int x0 = rng.below(8), y0 = rng.below(8), s = rng.below(2) ? 1 : -1;
    for (int v = 0; v < 8; ++v)
      for (int u = 0; u < 8; ++u) {
        const double c = std::cos((2 * x0 + 1) * u * M_PI / 16) * std::cos((2 * y0 + 1) * v * M_PI / 16);
        put(8 * v + u, (c * s >= 0) ? 2047 : -2048);
      }
    return b;
  }
  const bool dense = kind == 0 || kind == 6;
  const int count = dense ? 64 : 1 + rng.below(8);
  for (int k = 0; k < count; ++k) {
    const int pos = dense ? k : rng.below(64);
    int v;
    if (kind == 3) {
      v = rng.below(2) ? 2047 : -2048;
    } else {
      const int range = kind == 2 ? 300 : (kind == 6 ? 64 : 2048);
      v = rng.below(2 * range) - range;
    }
    put(pos, v);
  }
  if (t % 3 == 0) {
    for (int i = 0; i < 8; ++i) b.c[56 + i] = b.c[8 * i + 7] = 0;
    b.c[63] = static_cast<std::int16_t>(rng.below(2) ? 1 : -1);
    b.rows = (b.rows & 0x7F) | kIdctToggleOnly;
    b.cols &= 0x7F;
  }
  return b;
}

}  // namespace vbim::ipu::testing
