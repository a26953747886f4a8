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
#include "gs/twin_tiles.hpp"
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
    int tilesCopied = 0;  // taken from a twin (Twin) instead of blended
  };

  // Two blenders that make the same blends: the player's run and its fault-free reference (issue
  // #31), each the other's twin. Where the twin's last blend of a tile was from the same source
  // bytes with the same spec, starting from bytes this tile holds now (TwinTiles), this blend would
  // give the twin's tile as it is now: its bytes, change and fixed-point marks are copied instead
  // (in hash mode the copied bytes are still folded into the chain). Same bytes, change counts and
  // chain as blending; only host time is saved. Both must recordBlends().
  struct Twin {
    const TiledBlender* blender = nullptr;
    const Rgba8Image* image = nullptr;  // the lightmap the twin writes
    TwinTiles* equal = nullptr;         // facts read, and the copies' facts added
    bool runSide = false;               // this blender's counts are TwinTiles' run side
    // The twin's last blend (lastSourceId) was from a source holding the same bytes as this blend's.
    bool sameSource = false;
  };

  // Blends rows [rowBegin, rowEnd) of `src` into `dst`. rowBegin must be a multiple of 32 (a tile
  // row); rowEnd a multiple of 32 or the height. `sourceId` must change whenever the content of
  // `src` changes (e.g. the frame's sequence number and variant).
  Result blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, std::uint64_t sourceId, int rowBegin,
               int rowEnd, const Twin* twin = nullptr);
  Result blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, std::uint64_t sourceId) {
    return blend(dst, src, spec, sourceId, 0, height_);
  }
  // Forget every convergence mark and the hash chain (call when the lightmap is written by anything else).
  void invalidate() {
    forgetSettled();
    ++epoch_;
    hashedRows_ = 0;
  }
  // Keep, per tile, what its last blend was (change count before it, its largest change, the source
  // and spec it had), so that a twin can take its result (Twin). Costs a few stores per tile.
  void recordBlends();
  // Forget every tile's record (a twin cannot take a blend from them), e.g. when this blender's
  // lightmap stops being kept up to date because it mirrors its twin's (gs::Presenter::followTwin).
  void forgetAllRecords() { forgetRecords(0, tilesY_); }
  // A blend this blender did not make, because its lightmap held the bytes of `twin`'s and the twin
  // just made that very blend (same source bytes and spec, rows [rowBegin, rowEnd)): the change
  // counts move as this blend would have moved them, and each tile of the rows is noted equal in
  // `equal` (runSide: this blender's counts are its run side). The lightmap's bytes are not written
  // (the caller reads the twin's while they agree; the settled marks are forgotten with invalidate()
  // before this blender blends again). The twin must recordBlends(). Returns the blend's pop (the
  // largest change of the twin's blend over the rows). Throws GsError if the twin's last blend of a
  // tile in the rows is not recorded (16-bit, or without the convergence shortcut).
  int takeTwinBlend(const TiledBlender& twin, TwinTiles& equal, bool runSide, std::uint64_t sourceId,
                    const BlendSpec& spec, int rowBegin, int rowEnd);
  std::uint64_t lastSourceId() const { return lastSourceId_; }
  const BlendSpec& lastSpec() const { return lastSpec_; }
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
  // recordBlends: epoch_ moves whenever the source or the spec does (with the fixed-point marks);
  // per tile, the epoch, change count before, and largest change of its last blend (kNoEpoch: a
  // blend not recorded, 16-bit or without the convergence shortcut).
  static constexpr std::uint64_t kNoEpoch = ~std::uint64_t{0};
  std::uint64_t epoch_ = 0;
  bool record_ = false;
  std::vector<std::uint64_t> blendEpoch_;
  std::vector<std::uint64_t> blendPre_;
  std::vector<int> blendDelta_;
  // Hash mode: rowChain_[k] is the chain before tile row k (after the header word and the rows above
  // it), rowChain_[tilesY] after the image; entries 0..hashedRows_ hold the lightmap's bytes as they are.
  bool hash_;
  std::vector<HashChain> rowChain_;
  int hashedRows_ = 0;
  std::vector<int> rowDelta_;  // scratch: per tile of a tile row, its change (blendHashRows)
  std::vector<char> copied_;   // scratch: per tile of a tile row, copied from the twin

  void forgetSettled() { std::fill(settled_.begin(), settled_.end(), 0u); }
  void recordTile(std::size_t i, std::uint64_t pre, int delta) {
    blendEpoch_[i] = epoch_;
    blendPre_[i] = pre;
    blendDelta_[i] = delta;
  }
  void forgetRecords(int ty0, int ty1);
  // Whether tile i may be copied from the twin (Twin): its last blend was of this epoch's source and
  // spec, from bytes equal to this tile's now.
  bool twinHolds(const Twin& t, std::size_t i) const {
    const TiledBlender& b = *t.blender;
    if (b.blendEpoch_[i] != b.epoch_) return false;
    return t.runSide ? t.equal->equalAt(i, changes_[i], b.blendPre_[i])
                     : t.equal->equalAt(i, b.blendPre_[i], changes_[i]);
  }
  // After a copy: this tile and the twin's hold the same bytes at their counts now.
  void noteEqual(const Twin& t, std::size_t i) const {
    const std::uint64_t theirs = t.blender->changes_[i];
    if (t.runSide) {
      t.equal->setEqual(i, changes_[i], theirs);
    } else {
      t.equal->setEqual(i, theirs, changes_[i]);
    }
  }
  bool twinUsable(const Twin* t, const BlendSpec& spec) const;
  void copyTwinBytes(const Twin& t, Rgba8Image& dst, int tx, int ty) const;
  void hashRow(const Rgba8Image& dst, int ty);
  void blendHashed(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty, std::uint32_t allRows,
                   const Twin* twin, Result& r);
  void blend16(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty0, int ty1, Result& r);
};

}  // namespace vbim::gs
