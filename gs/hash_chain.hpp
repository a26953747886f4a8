// The chain of the per-vsync frame hash (its definition: player/frame_hash.hpp, docs/player.md
// "hashes.txt"): 64-bit little-endian words folded into four FNV-1a lanes by word index mod 4. It
// lives in gs so that the blend can fold a lightmap row into it while the row is in registers and
// L1 (gs/tiled_blender.hpp, hash mode): the chain is bound by its multiply latency, the blend by
// throughput, so the two share a pass. Header only: the SIMD kernels inline it.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace vbim::gs {

struct HashChain {
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;  // FNV-1a 64
  std::uint64_t lanes[4] = {0xcbf29ce484222325ull, 0xcbf29ce484222326ull, 0xcbf29ce484222327ull, 0xcbf29ce484222328ull};
  std::uint64_t count = 0;  // words folded so far: the next word's lane is count & 3

  // The 8 bytes at p as a little-endian word: one load on a little-endian host, bytes assembled
  // otherwise, so the hash is the same everywhere.
  static std::uint64_t loadLe(const std::uint8_t* p) {
    std::uint64_t w = 0;
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(&w, p, sizeof w);
    } else {
      for (int i = 7; i >= 0; --i) w = (w << 8) | p[i];
    }
    return w;
  }

  void word(std::uint64_t w) {
    std::uint64_t& l = lanes[count & 3];
    l = (l ^ w) * kPrime;
    ++count;
  }

  // The n bytes at p as words in order; a last partial word is zero-padded (so every call but an
  // image's last must pass a multiple of 8 bytes).
  void addBytes(const std::uint8_t* p, std::size_t n) {
    std::size_t i = 0;
    // Word order fixes the lane. Single words until the next is lane 0's, then four words at a time
    // with the lanes in registers: four independent multiply chains that overlap. No SIMD: x86 has
    // no fast 64-bit vector multiply, so four scalar chains are the floor.
    for (; i + 8 <= n && (count & 3) != 0; i += 8) word(loadLe(p + i));
    if (i + 32 <= n) {
      std::uint64_t l0 = lanes[0], l1 = lanes[1], l2 = lanes[2], l3 = lanes[3];
      const std::size_t blocks = (n - i) / 32;
      for (std::size_t b = 0; b < blocks; ++b, i += 32) {
        l0 = (l0 ^ loadLe(p + i)) * kPrime;
        l1 = (l1 ^ loadLe(p + i + 8)) * kPrime;
        l2 = (l2 ^ loadLe(p + i + 16)) * kPrime;
        l3 = (l3 ^ loadLe(p + i + 24)) * kPrime;
      }
      lanes[0] = l0;
      lanes[1] = l1;
      lanes[2] = l2;
      lanes[3] = l3;
      count += 4 * blocks;
    }
    for (; i + 8 <= n; i += 8) word(loadLe(p + i));
    if (i < n) {
      std::uint8_t tail[8] = {};
      std::memcpy(tail, p + i, n - i);
      word(loadLe(tail));
    }
  }

  // An image's header word: width << 32 | height.
  void addHeader(int width, int height) {
    word((static_cast<std::uint64_t>(static_cast<std::uint32_t>(width)) << 32) | static_cast<std::uint32_t>(height));
  }
};

}  // namespace vbim::gs
