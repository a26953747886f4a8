// The 64-bit hash of a vsync's output written to hashes.txt: the lightmap bytes, then the sky bytes.
//
// Definition (docs/player.md "hashes.txt"): for each image in turn, its width and height as one
// 64-bit word (width << 32 | height), then its RGBA bytes as little-endian 64-bit words (the last one
// zero-padded), are folded into four lanes by word index mod 4:
//   lane = (lane ^ word) * 0x100000001b3 (FNV-1a 64 prime), starting from 0xcbf29ce484222325 + lane number;
// the result is lane0 ^ rotl(lane1, 16) ^ rotl(lane2, 32) ^ rotl(lane3, 48), then mixed by the
// splitmix64 finaliser. Integer only; identical on every machine.
#pragma once

#include <cstdint>
#include <string>

#include "runtime/image.hpp"

namespace vbim::player {

class FrameHasher {
 public:
  void add(const Rgba8Image& image);
  std::uint64_t digest() const;

 private:
  void word(std::uint64_t w);
  std::uint64_t lanes_[4] = {0xcbf29ce484222325ull, 0xcbf29ce484222326ull, 0xcbf29ce484222327ull,
                             0xcbf29ce484222328ull};
  std::uint64_t count_ = 0;
};

// Hash of a lightmap and (optionally) a sky image; sky may be null.
std::uint64_t frameHash(const Rgba8Image& lightmap, const Rgba8Image* sky);
// 16 lowercase hex digits.
std::string hashHex(std::uint64_t h);

}  // namespace vbim::player
