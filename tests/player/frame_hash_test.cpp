// The per-vsync frame hash (player/frame_hash.hpp): known answers computed by an independent
// implementation of the definition in docs/player.md ("hashes.txt"), and the fast path against a
// word-by-word scalar reference on images of every size class (the 32-byte blocks, the single
// words before and after them, a zero-padded last word).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "player/frame_hash.hpp"

namespace vbim::player {
namespace {

Rgba8Image pattern(int w, int h, std::uint32_t mul, std::uint32_t add, bool square) {
  Rgba8Image img(w, h);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    const auto k = static_cast<std::uint32_t>(i);
    img.pixels[i] = static_cast<std::uint8_t>((square ? k * k * mul : k * mul) + add);
  }
  return img;
}

// The definition, one word at a time: the reference the fast path must match.
std::uint64_t referenceHash(const std::vector<const Rgba8Image*>& images) {
  std::uint64_t lanes[4] = {0xcbf29ce484222325ull, 0xcbf29ce484222326ull, 0xcbf29ce484222327ull, 0xcbf29ce484222328ull};
  std::uint64_t count = 0;
  auto word = [&](std::uint64_t w) {
    std::uint64_t& l = lanes[count++ & 3];
    l = (l ^ w) * 0x100000001b3ull;
  };
  for (const Rgba8Image* img : images) {
    word((static_cast<std::uint64_t>(static_cast<std::uint32_t>(img->width)) << 32) |
         static_cast<std::uint32_t>(img->height));
    for (std::size_t i = 0; i < img->pixels.size(); i += 8) {
      std::uint64_t w = 0;
      for (std::size_t b = 0; b < 8; ++b) {
        const std::uint64_t byte = i + b < img->pixels.size() ? img->pixels[i + b] : 0;
        w |= byte << (8 * b);
      }
      word(w);
    }
  }
  auto rotl = [](std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); };
  std::uint64_t h = lanes[0] ^ rotl(lanes[1], 16) ^ rotl(lanes[2], 32) ^ rotl(lanes[3], 48);
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  h ^= h >> 31;
  return h;
}

TEST(FrameHash, KnownAnswers) {
  const Rgba8Image a = pattern(3, 2, 37, 11, false);
  const Rgba8Image b = pattern(17, 9, 13, 5, true);
  const Rgba8Image c = pattern(64, 32, 7, 0, false);
  EXPECT_EQ(hashHex(frameHash(a, nullptr)), "96c6c9a98b31562f");
  EXPECT_EQ(hashHex(frameHash(b, &a)), "eec169d40725f5ce");
  EXPECT_EQ(hashHex(frameHash(c, &b)), "cea2bd710e327d47");
}

TEST(FrameHash, FastPathMatchesTheWordByWordReference) {
  std::mt19937 rng(11);
  for (int w = 1; w <= 19; ++w) {
    for (int h = 1; h <= 5; ++h) {
      Rgba8Image lm(w, h);
      Rgba8Image sky(h + 2, w);
      for (auto& px : lm.pixels) px = static_cast<std::uint8_t>(rng());
      for (auto& px : sky.pixels) px = static_cast<std::uint8_t>(rng());
      ASSERT_EQ(frameHash(lm, nullptr), referenceHash({&lm})) << w << "x" << h;
      ASSERT_EQ(frameHash(lm, &sky), referenceHash({&lm, &sky})) << w << "x" << h;
    }
  }
  Rgba8Image big(256, 256);
  for (auto& px : big.pixels) px = static_cast<std::uint8_t>(rng());
  Rgba8Image sky(128, 64);
  for (auto& px : sky.pixels) px = static_cast<std::uint8_t>(rng());
  EXPECT_EQ(frameHash(big, &sky), referenceHash({&big, &sky}));
}

// Random sizes, so that each image starts at a random lane (count of words so far mod 4) and ends
// with half or all of its last word filled.
TEST(FrameHash, FastPathMatchesTheReferenceOnRandomSizes) {
  std::mt19937 rng(1717);
  for (int trial = 0; trial < 300; ++trial) {
    const auto side = [&rng] { return 1 + static_cast<int>(rng() % 97); };
    Rgba8Image lm(side(), side());
    Rgba8Image sky(side(), side());
    for (auto& px : lm.pixels) px = static_cast<std::uint8_t>(rng());
    for (auto& px : sky.pixels) px = static_cast<std::uint8_t>(rng());
    ASSERT_EQ(frameHash(lm, &sky), referenceHash({&lm, &sky}))
        << lm.width << "x" << lm.height << " + " << sky.width << "x" << sky.height;
  }
}

TEST(FrameHash, EveryByteCounts) {
  Rgba8Image img = pattern(8, 8, 3, 1, false);
  const std::uint64_t before = frameHash(img, nullptr);
  for (std::size_t i = 0; i < img.pixels.size(); i += 37) {
    img.pixels[i] ^= 1;
    EXPECT_NE(frameHash(img, nullptr), before) << "byte " << i;
    img.pixels[i] ^= 1;
  }
  EXPECT_EQ(frameHash(img, nullptr), before);
}

}  // namespace
}  // namespace vbim::player
