#include "player/frame_hash.hpp"

namespace vbim::player {

void FrameHasher::add(const Rgba8Image& image) {
  chain_.addHeader(image.width, image.height);
  chain_.addBytes(image.pixels.data(), image.pixels.size());
}

void FrameHasher::addHeader(int width, int height) {
  chain_.addHeader(width, height);
}

void FrameHasher::addBytes(const std::uint8_t* p, std::size_t n) {
  chain_.addBytes(p, n);
}

namespace {

std::uint64_t rotl(std::uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

}  // namespace

std::uint64_t FrameHasher::digest() const {
  const std::uint64_t* l = chain_.lanes;
  std::uint64_t h = l[0] ^ rotl(l[1], 16) ^ rotl(l[2], 32) ^ rotl(l[3], 48);
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
