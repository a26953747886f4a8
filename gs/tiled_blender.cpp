#include "gs/tiled_blender.hpp"

#include <algorithm>
#include <cstring>

#include "gs/blend16.hpp"
#include "gs/error.hpp"

namespace vbim::gs {

TiledBlender::TiledBlender(int width, int height, const BlendKernels& kernels, bool convergenceAware, bool hashChain)
    : width_(width),
      height_(height),
      tilesX_((width + kTileWidth - 1) / kTileWidth),
      tilesY_((height + kTileHeight - 1) / kTileHeight),
      kernels_(&kernels),
      aware_(convergenceAware),
      settled_(static_cast<std::size_t>(tilesX_) * tilesY_, 0),
      changes_(settled_.size(), 0),
      hash_(hashChain) {
  if (hash_) {
    rowChain_.resize(static_cast<std::size_t>(tilesY_) + 1);
    rowChain_[0].addHeader(width_, height_);
    rowDelta_.resize(static_cast<std::size_t>(tilesX_));
    copied_.resize(static_cast<std::size_t>(tilesX_));
  }
}

void TiledBlender::hashRow(const Rgba8Image& dst, int ty) {
  const int y0 = ty * kTileHeight;
  const int y1 = std::min(y0 + kTileHeight, height_);
  HashChain c = rowChain_[static_cast<std::size_t>(ty)];
  c.addBytes(dst.row(y0), static_cast<std::size_t>(width_) * 4 * (y1 - y0));
  rowChain_[static_cast<std::size_t>(ty) + 1] = c;
  hashedRows_ = ty + 1;
}

void TiledBlender::recordBlends() {
  record_ = true;
  blendEpoch_.assign(settled_.size(), kNoEpoch);
  blendPre_.assign(settled_.size(), 0);
  blendDelta_.assign(settled_.size(), 0);
}

void TiledBlender::forgetRecords(int ty0, int ty1) {
  if (!record_) return;
  const auto first = static_cast<std::ptrdiff_t>(ty0) * tilesX_;
  const auto last = static_cast<std::ptrdiff_t>(ty1) * tilesX_;
  std::fill(blendEpoch_.begin() + first, blendEpoch_.begin() + last, kNoEpoch);
}

int TiledBlender::takeTwinBlend(const TiledBlender& twin, TwinTiles& equal, bool runSide, std::uint64_t sourceId,
                                const BlendSpec& spec, int rowBegin, int rowEnd) {
  if (!twin.record_ || twin.settled_.size() != settled_.size() || equal.size() != settled_.size()) {
    throw GsError("a blend taken from a twin that does not record its blends, or of another size");
  }
  lastSourceId_ = sourceId;
  lastSpec_ = spec;
  const int ty0 = rowBegin / kTileHeight;
  const int ty1 = (std::min(rowEnd, height_) + kTileHeight - 1) / kTileHeight;
  int pop = 0;
  for (auto i = static_cast<std::size_t>(ty0) * tilesX_; i < static_cast<std::size_t>(ty1) * tilesX_; ++i) {
    if (twin.blendEpoch_[i] != twin.epoch_) throw GsError("a blend taken from a twin whose blend was not recorded");
    const int delta = twin.blendDelta_[i];
    if (delta != 0) ++changes_[i];
    pop = std::max(pop, delta);
    if (runSide) {
      equal.setEqual(i, changes_[i], twin.changes_[i]);
    } else {
      equal.setEqual(i, twin.changes_[i], changes_[i]);
    }
  }
  if (hash_) hashedRows_ = std::min(hashedRows_, ty0);
  return pop;
}

bool TiledBlender::twinUsable(const Twin* t, const BlendSpec& spec) const {
  return t != nullptr && t->sameSource && t->blender != nullptr && t->blender->record_ && t->equal != nullptr &&
         t->image != nullptr && t->equal->size() == settled_.size() && t->blender->width_ == width_ &&
         t->blender->height_ == height_ && t->image->width == width_ && t->image->height == height_ && !spec.psmct16 &&
         t->blender->lastSpec_ == spec;
}

// The twin's tile (tx, ty) as it is now into dst.
void TiledBlender::copyTwinBytes(const Twin& t, Rgba8Image& dst, int tx, int ty) const {
  const int x0 = tx * kTileWidth;
  const int y0 = ty * kTileHeight;
  const auto bytes = static_cast<std::size_t>(std::min(kTileWidth, width_ - x0)) * 4;
  const int rows = std::min(kTileHeight, height_ - y0);
  const std::size_t left = static_cast<std::size_t>(x0) * 4;
  for (int y = y0; y < y0 + rows; ++y) std::memcpy(dst.row(y) + left, t.image->row(y) + left, bytes);
}

const HashChain& TiledBlender::hashChain(const Rgba8Image& dst) {
  if (!hash_) throw GsError("the frame hash chain of a blender not in hash mode");
  while (hashedRows_ < tilesY_) hashRow(dst, hashedRows_);
  return rowChain_.back();
}

TiledBlender::Result TiledBlender::blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec,
                                         std::uint64_t sourceId, int rowBegin, int rowEnd, const Twin* twin) {
  if (dst.width != width_ || dst.height != height_ || !src.sameSize(dst)) {
    throw GsError("blend of a " + std::to_string(src.width) + "x" + std::to_string(src.height) + " frame into a " +
                  std::to_string(dst.width) + "x" + std::to_string(dst.height) + " lightmap; expected both " +
                  std::to_string(width_) + "x" + std::to_string(height_));
  }
  if (sourceId != lastSourceId_ || !(spec == lastSpec_)) {
    forgetSettled();  // the bytes stay: the hash chain holds
    ++epoch_;
    lastSourceId_ = sourceId;
    lastSpec_ = spec;
  }
  Result r;
  const std::size_t stride = static_cast<std::size_t>(width_) * 4;  // bytes per lightmap row
  const int ty0 = rowBegin / kTileHeight;
  const int ty1 = (std::min(rowEnd, height_) + kTileHeight - 1) / kTileHeight;
  if (spec.psmct16 || !aware_) forgetRecords(ty0, ty1);  // what a twin cannot take (see Twin)
  if (spec.psmct16) {
    blend16(dst, src, spec, ty0, ty1, r);
    return r;
  }
  const bool fromTwin = aware_ && twinUsable(twin, spec);
  for (int ty = ty0; ty < ty1; ++ty) {
    const int y0 = ty * kTileHeight;
    const int y1 = std::min(y0 + kTileHeight, height_);
    if (!aware_) {
      // Whole rows at once: the kernels run longest without a call boundary.
      const std::size_t pixels = static_cast<std::size_t>(width_) * (y1 - y0);
      const int pop = kernels_->blendDelta(dst.row(y0), src.row(y0), pixels, spec);
      if (pop > 0) {  // some byte of the tile row moved: count a change for each of its tiles
        for (int tx = 0; tx < tilesX_; ++tx) ++changes_[static_cast<std::size_t>(ty) * tilesX_ + tx];
        hashedRows_ = std::min(hashedRows_, ty);
      }
      r.pop = std::max(r.pop, pop);
      r.tilesBlended += tilesX_;
      continue;
    }
    const std::uint32_t allRows = y1 - y0 == 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << (y1 - y0)) - 1;
    if (hash_) {
      blendHashed(dst, src, spec, ty, allRows, fromTwin ? twin : nullptr, r);
      continue;
    }
    for (int tx = 0; tx < tilesX_; ++tx) {
      const std::size_t i = static_cast<std::size_t>(ty) * tilesX_ + tx;
      std::uint32_t& settled = settled_[i];
      if (settled == allRows) {
        if (record_) recordTile(i, changes_[i], 0);  // a blend would change nothing
        ++r.tilesSkipped;
        continue;
      }
      const int x0 = tx * kTileWidth;
      const std::size_t w = static_cast<std::size_t>(std::min(kTileWidth, width_ - x0));
      const auto rows = static_cast<std::size_t>(y1 - y0);
      const std::uint64_t before = changes_[i];
      if (fromTwin && twinHolds(*twin, i)) {
        copyTwinBytes(*twin, dst, tx, ty);
        const TiledBlender& b = *twin->blender;
        const int pop = b.blendDelta_[i];
        settled = pop == 0 ? allRows : b.settled_[i];  // as a blend marks them
        if (pop != 0) ++changes_[i];                   // the twin's blend changed its tile (its count moved)
        if (record_) recordTile(i, before, pop);
        noteEqual(*twin, i);
        r.pop = std::max(r.pop, pop);
        ++r.tilesCopied;
        continue;
      }
      const std::size_t left = static_cast<std::size_t>(x0) * 4;  // bytes into the row
      const int pop =
          kernels_->blendRectDelta(dst.row(y0) + left, stride, src.row(y0) + left, stride, w, rows, spec, &settled);
      // Rows that changed nothing are at their fixed point even where the per-row test cannot tell
      // (a Wrap-mode step of exactly 256).
      // pop is the largest change of any byte: zero when the tile's bytes are as they were.
      if (pop == 0) {
        settled = allRows;
      } else {
        ++changes_[i];
      }
      if (record_) recordTile(i, before, pop);
      r.pop = std::max(r.pop, pop);
      ++r.tilesBlended;
    }
  }
  return r;
}

// The 16-bit path, scalar only (gs/blend16.hpp), tile by tile. Its per-pixel result depends on the
// texel's position (DIMX), which the kernels do not see; a blend that changes nothing in a tile
// would change nothing again (the same inputs at the same places), so such a tile is skipped until
// the source or the spec changes, as in the 32-bit path. The hash chain is folded lazily.
void TiledBlender::blend16(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty0, int ty1, Result& r) {
  const std::size_t stride = static_cast<std::size_t>(width_) * 4;
  for (int ty = ty0; ty < ty1; ++ty) {
    const int y0 = ty * kTileHeight;
    const int y1 = std::min(y0 + kTileHeight, height_);
    for (int tx = 0; tx < tilesX_; ++tx) {
      std::uint32_t& settled = settled_[static_cast<std::size_t>(ty) * tilesX_ + tx];
      if (aware_ && settled != 0) {
        ++r.tilesSkipped;
        continue;
      }
      const int x0 = tx * kTileWidth;
      const std::size_t w = static_cast<std::size_t>(std::min(kTileWidth, width_ - x0));
      const std::size_t left = static_cast<std::size_t>(x0) * 4;
      const int pop = blend16Rect(dst.row(y0) + left, stride, src.row(y0) + left, stride, w,
                                  static_cast<std::size_t>(y1 - y0), x0, y0, spec);
      if (pop == 0) {
        settled = ~std::uint32_t{0};
      } else {
        ++changes_[static_cast<std::size_t>(ty) * tilesX_ + tx];
        hashedRows_ = std::min(hashedRows_, ty);
      }
      r.pop = std::max(r.pop, pop);
      ++r.tilesBlended;
    }
  }
}

// One tile row in hash mode: its unsettled tiles blended and, when the rows above are folded into
// the chain, folded too in the same pass. Same bytes, marks and counts as the loop in blend().
void TiledBlender::blendHashed(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec, int ty,
                               std::uint32_t allRows, const Twin* twin, Result& r) {
  const std::size_t first = static_cast<std::size_t>(ty) * tilesX_;
  std::uint32_t* settled = settled_.data() + first;
  const bool allSettled = std::all_of(settled, settled + tilesX_, [allRows](std::uint32_t m) { return m == allRows; });
  if (allSettled) {
    if (record_) {
      for (std::size_t i = first; i < first + static_cast<std::size_t>(tilesX_); ++i) recordTile(i, changes_[i], 0);
    }
    r.tilesSkipped += tilesX_;
    // Nothing moves; the rows above were just folded (an earlier tile row changed): fold this one
    // too while the chain is at hand, since the vsync's hash will need it.
    if (hashedRows_ == ty) hashRow(dst, ty);
    return;
  }
  const int y0 = ty * kTileHeight;
  const int y1 = std::min(y0 + kTileHeight, height_);
  std::fill(rowDelta_.begin(), rowDelta_.end(), 0);
  // Settled tiles are skipped by their masks inside the kernel; count them as the loop does.
  for (int tx = 0; tx < tilesX_; ++tx) (settled[tx] == allRows ? r.tilesSkipped : r.tilesBlended) += 1;
  // Tiles the twin holds are copied and marked settled for the kernel, which then only folds them.
  if (twin != nullptr) {
    for (int tx = 0; tx < tilesX_; ++tx) {
      const std::size_t i = first + static_cast<std::size_t>(tx);
      copied_[static_cast<std::size_t>(tx)] = settled[tx] != allRows && twinHolds(*twin, i);
      if (!copied_[static_cast<std::size_t>(tx)]) continue;
      copyTwinBytes(*twin, dst, tx, ty);
      settled[tx] = allRows;
      --r.tilesBlended;
      ++r.tilesCopied;
    }
  }
  const bool fold = hashedRows_ >= ty;
  HashChain chain = rowChain_[static_cast<std::size_t>(ty)];
  kernels_->blendHashRows(dst.row(y0), src.row(y0), static_cast<std::size_t>(width_), static_cast<std::size_t>(y1 - y0),
                          static_cast<std::size_t>(kTileWidth), spec, settled, rowDelta_.data(),
                          fold ? &chain : nullptr);
  bool changed = false;
  for (int tx = 0; tx < tilesX_; ++tx) {
    int pop = rowDelta_[static_cast<std::size_t>(tx)];
    const std::size_t i = first + static_cast<std::size_t>(tx);
    const bool copied = twin != nullptr && copied_[static_cast<std::size_t>(tx)];
    if (copied) {  // the twin's change and marks (a copy that changed nothing is settled below)
      pop = twin->blender->blendDelta_[i];
      settled[tx] = twin->blender->settled_[i];
    }
    if (record_) recordTile(i, changes_[i], pop);
    if (pop == 0) {
      settled[tx] = allRows;  // as in blend(): a tile that did not change is at its fixed point
    } else {
      ++changes_[i];
      changed = true;
    }
    if (copied) noteEqual(*twin, i);
    r.pop = std::max(r.pop, pop);
  }
  if (fold) {
    rowChain_[static_cast<std::size_t>(ty) + 1] = chain;
    // The chain past this row holds if its bytes did not move.
    hashedRows_ = changed ? ty + 1 : std::max(hashedRows_, ty + 1);
  } else if (changed) {
    hashedRows_ = std::min(hashedRows_, ty);
  }
}

}  // namespace vbim::gs
