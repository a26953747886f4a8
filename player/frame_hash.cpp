#include "player/frame_hash.hpp"

#include <cstring>

namespace vbim::player {

namespace {

constexpr std::uint64_t kPrime = 0x100000001b3ull;

std::uint64_t rotl(std::uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

std::uint64_t loadLe(const std::uint8_t* p) {
  std::uint64_t w = 0;
  for (int i = 7; i >= 0; --i) w = (w << 8) | p[i];
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
  // Four independent lanes: the multiply chains overlap. Word order fixes the lane (count_ & 3).
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
