// Blends a source frame into the lightmap, tile by tile (64x32 pixels: one PSMCT32 page), with an
// optional host-side shortcut: a row of a tile that a blend left at its fixed point for that source
// and spec (gs/blend.hpp, spanAtFixedPoint) would not change if blended again, so it is skipped, and
// so is a tile whose rows all are, until the source or the spec changes. A blend that changes a
// tile's last moving rows marks them at once, so a converged tile costs no extra pass to be found.
// The result is bit-identical to blending everything (the tests check it); only host time is saved,
// never simulated time (the GS still draws every pixel). It counts, per tile, the blends that
// changed a byte of it, so that a reader of the lightmap can tell which tiles moved since it last
// looked (the player's lag compares only those: gs/lag_meter.hpp, TiledDifference).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gs/blend.hpp"
#include "gs/hash_chain.hpp"
#include "runtime/image.hpp"

namespace vbim::gs {

inline constexpr int kTileWidth = 64;
inline constexpr int kTileHeight = 32;
static_assert(kTileHeight <= 32, "a tile's settled rows are one 32-bit mask");

// Hash mode (hashChain = true) keeps the frame hash's chain (gs/hash_chain.hpp) of the lightmap's
// bytes, header word first, as it would be at the start of every tile row: a tile row that is
// blended is folded into the chain in the same pass (BlendKernels::blendHashRows) when the rows
// above it are already folded, and hashChain() folds whatever is left. A vsync that changes only the
// lower tiles hashes from the first tile row that moved; one that changes nothing hashes nothing.
class TiledBlender {
 public:
  TiledBlender(int width, int height, const BlendKernels& kernels, bool convergenceAware, bool hashChain = false);

  struct Result {
    int pop = 0;  // largest per-byte change made
    int tilesBlended = 0;
    int tilesSkipped = 0;
  };

  // Blends rows [rowBegin, rowEnd) of `src` into `dst`. rowBegin must be a multiple of 32 (a tile
  // row); rowEnd a multiple of 32 or the height. `sourceId` must change whenever the content of
  // `src` changes (e.g. the frame's sequence number and variant).
  Result blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, std::uint64_t sourceId, int rowBegin,
               int rowEnd);
  Result blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, std::uint64_t sourceId) {
    return blend(dst, src, spec, sourceId, 0, height_);
  }
  // Forget every convergence mark and the hash chain (call when the lightmap is written by anything else).
  void invalidate() {
    forgetSettled();
    hashedRows_ = 0;
  }
  // Hash mode: the chain after the header word and every byte of `dst` (the image this blender
  // writes, as it is now). Throws GsError without hash mode.
  const HashChain& hashChain(const Rgba8Image& dst);

  int tilesX() const { return tilesX_; }
  int tilesY() const { return tilesY_; }
  // Per tile (row-major, tilesX() per row): how many blends changed at least one of its bytes. A
  // tile whose count did not move holds the same bytes as before.
  const std::vector<std::uint64_t>& tileChanges() const { return changes_; }

 private:
  int width_;
  int height_;
  int tilesX_;
  int tilesY_;
  const BlendKernels* kernels_;
  bool aware_;
  std::uint64_t lastSourceId_ = ~std::uint64_t{0};
  BlendSpec lastSpec_{};
  std::vector<std::uint32_t> settled_;  // per tile: its rows at their fixed point (BlendRectDeltaFn)
  std::vector<std::uint64_t> changes_;  // per tile: blends that changed it (tileChanges())
  // Hash mode: rowChain_[k] is the chain before tile row k (after the header word and the rows above
  // it), rowChain_[tilesY] after the image; entries 0..hashedRows_ hold the lightmap's bytes as they are.
  bool hash_;
  std::vector<HashChain> rowChain_;
  int hashedRows_ = 0;
  std::vector<int> rowDelta_;  // scratch: per tile of a tile row, its change (blendHashRows)

  void forgetSettled() { std::fill(settled_.begin(), settled_.end(), 0u); }
  void hashRow(const Rgba8Image& dst, int ty);
  void blendHashed(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty, std::uint32_t allRows,
                   Result& r);
  void blend16(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty0, int ty1, Result& r);
};

}  // namespace vbim::gs
