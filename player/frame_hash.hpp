// The 64-bit hash of a vsync's output written to hashes.txt: the lightmap bytes, then the sky bytes.
//
// Definition (docs/player.md "hashes.txt"): for each image in turn, its width and height as one
// 64-bit word (width << 32 | height), then its RGBA bytes as little-endian 64-bit words (the last one
// zero-padded), are folded into four lanes by word index mod 4:
//   lane = (lane ^ word) * 0x100000001b3 (FNV-1a 64 prime), starting from 0xcbf29ce484222325 + lane number;
// the result is lane0 ^ rotl(lane1, 16) ^ rotl(lane2, 32) ^ rotl(lane3, 48), then mixed by the
// splitmix64 finaliser. Integer only; identical on every machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "gs/hash_chain.hpp"
#include "runtime/image.hpp"

namespace vbim::player {

class FrameHasher {
 public:
  void add(const Rgba8Image& image);
  // add() in pieces: the image's header word, then its bytes in order. Every piece but the image's
  // last must be a whole number of words (n a multiple of 8); the last is zero-padded.
  void addHeader(int width, int height);
  void addBytes(const std::uint8_t* p, std::size_t n);
  std::uint64_t digest() const;
  // The chain itself (the blender folds lightmap rows into it: gs/tiled_blender.hpp, hash mode).
  explicit FrameHasher(const gs::HashChain& chain = {}) : chain_(chain) {}
  const gs::HashChain& chain() const { return chain_; }

 private:
  gs::HashChain chain_;
};

// Hash of a lightmap and (optionally) a sky image; sky may be null.
std::uint64_t frameHash(const Rgba8Image& lightmap, const Rgba8Image* sky);
// 16 lowercase hex digits.
std::string hashHex(std::uint64_t h);

}  // namespace vbim::player
