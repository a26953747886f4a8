#include "player/frame_hash.hpp"

#include <bit>
#include <cstring>

namespace vbim::player {

namespace {

constexpr std::uint64_t kPrime = 0x100000001b3ull;

std::uint64_t rotl(std::uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

// The 8 bytes at p as a little-endian word: one load on a little-endian host, bytes assembled
// otherwise, so the digest is the same everywhere.
std::uint64_t loadLe(const std::uint8_t* p) {
  std::uint64_t w = 0;
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(&w, p, sizeof w);
  } else {
    for (int i = 7; i >= 0; --i) w = (w << 8) | p[i];
  }
  return w;
}

}  // namespace

void FrameHasher::word(std::uint64_t w) {
  std::uint64_t& l = lanes_[count_ & 3];
  l = (l ^ w) * kPrime;
  ++count_;
}

void FrameHasher::add(const Rgba8Image& image) {
  word((static_cast<std::uint64_t>(static_cast<std::uint32_t>(image.width)) << 32) |
       static_cast<std::uint32_t>(image.height));
  const std::uint8_t* p = image.pixels.data();
  const std::size_t n = image.pixels.size();
  std::size_t i = 0;
  // Word order fixes the lane (count_ & 3). Single words until the next word is lane 0's, then four
  // words at a time with the lanes in registers: four independent multiply chains that overlap.
  // No SIMD path: the definition fixes four lanes, each a serial chain of 64-bit multiplies, and x86
  // vectors have no fast 64-bit multiply (none in AVX2; AVX-512's vpmullq has several times imul's
  // latency), so four scalar chains are the floor. bench_frame_hash: about 18 GB/s, as fast as
  // copying the same bytes.
  for (; i + 8 <= n && (count_ & 3) != 0; i += 8) word(loadLe(p + i));
  if (i + 32 <= n) {
    std::uint64_t l0 = lanes_[0], l1 = lanes_[1], l2 = lanes_[2], l3 = lanes_[3];
    const std::size_t blocks = (n - i) / 32;
    for (std::size_t b = 0; b < blocks; ++b, i += 32) {
      l0 = (l0 ^ loadLe(p + i)) * kPrime;
      l1 = (l1 ^ loadLe(p + i + 8)) * kPrime;
      l2 = (l2 ^ loadLe(p + i + 16)) * kPrime;
      l3 = (l3 ^ loadLe(p + i + 24)) * kPrime;
    }
    lanes_[0] = l0;
    lanes_[1] = l1;
    lanes_[2] = l2;
    lanes_[3] = l3;
    count_ += 4 * blocks;
  }
  for (; i + 8 <= n; i += 8) word(loadLe(p + i));
  if (i < n) {
    std::uint8_t tail[8] = {};
    std::memcpy(tail, p + i, n - i);
    word(loadLe(tail));
  }
}

std::uint64_t FrameHasher::digest() const {
  std::uint64_t h = lanes_[0] ^ rotl(lanes_[1], 16) ^ rotl(lanes_[2], 32) ^ rotl(lanes_[3], 48);
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  h ^= h >> 31;
  return h;
}

std::uint64_t frameHash(const Rgba8Image& lightmap, const Rgba8Image* sky) {
  FrameHasher h;
  h.add(lightmap);
  if (sky != nullptr) h.add(*sky);
  return h.digest();
}

std::string hashHex(std::uint64_t h) {
  static const char* kDigits = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, h >>= 4) s[static_cast<std::size_t>(i)] = kDigits[h & 15];
  return s;
}

}  // namespace vbim::player
