#include "gs/tiled_blender.hpp"

#include <algorithm>

#include "gs/error.hpp"

namespace vbim::gs {

TiledBlender::TiledBlender(int width, int height, const BlendKernels& kernels, bool convergenceAware)
    : width_(width),
      height_(height),
      tilesX_((width + kTileWidth - 1) / kTileWidth),
      tilesY_((height + kTileHeight - 1) / kTileHeight),
      kernels_(&kernels),
      aware_(convergenceAware),
      settled_(static_cast<std::size_t>(tilesX_) * tilesY_, 0),
      changes_(settled_.size(), 0) {}

TiledBlender::Result TiledBlender::blend(Rgba8Image& dst, const Rgba8Image& src, const BlendSpec& spec,
                                         std::uint64_t sourceId, int rowBegin, int rowEnd) {
  if (dst.width != width_ || dst.height != height_ || !src.sameSize(dst)) {
    throw GsError("blend of a " + std::to_string(src.width) + "x" + std::to_string(src.height) + " frame into a " +
                  std::to_string(dst.width) + "x" + std::to_string(dst.height) + " lightmap; expected both " +
                  std::to_string(width_) + "x" + std::to_string(height_));
  }
  if (sourceId != lastSourceId_ || !(spec == lastSpec_)) {
    invalidate();
    lastSourceId_ = sourceId;
    lastSpec_ = spec;
  }
  Result r;
  const std::size_t stride = static_cast<std::size_t>(width_) * 4;  // bytes per lightmap row
  const int ty0 = rowBegin / kTileHeight;
  const int ty1 = (std::min(rowEnd, height_) + kTileHeight - 1) / kTileHeight;
  for (int ty = ty0; ty < ty1; ++ty) {
    const int y0 = ty * kTileHeight;
    const int y1 = std::min(y0 + kTileHeight, height_);
    if (!aware_) {
      // Whole rows at once: the kernels run longest without a call boundary.
      const std::size_t pixels = static_cast<std::size_t>(width_) * (y1 - y0);
      const int pop = kernels_->blendDelta(dst.row(y0), src.row(y0), pixels, spec);
      if (pop > 0) {  // some byte of the tile row moved: count a change for each of its tiles
        for (int tx = 0; tx < tilesX_; ++tx) ++changes_[static_cast<std::size_t>(ty) * tilesX_ + tx];
      }
      r.pop = std::max(r.pop, pop);
      r.tilesBlended += tilesX_;
      continue;
    }
    const std::uint32_t allRows = y1 - y0 == 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << (y1 - y0)) - 1;
    for (int tx = 0; tx < tilesX_; ++tx) {
      std::uint32_t& settled = settled_[static_cast<std::size_t>(ty) * tilesX_ + tx];
      if (settled == allRows) {
        ++r.tilesSkipped;
        continue;
      }
      const int x0 = tx * kTileWidth;
      const std::size_t w = static_cast<std::size_t>(std::min(kTileWidth, width_ - x0));
      const std::size_t left = static_cast<std::size_t>(x0) * 4;  // bytes into the row
      const int pop = kernels_->blendRectDelta(dst.row(y0) + left, stride, src.row(y0) + left, stride, w,
                                               static_cast<std::size_t>(y1 - y0), spec, &settled);
      // Rows that changed nothing are at their fixed point even where the per-row test cannot tell
      // (a Wrap-mode step of exactly 256).
      // pop is the largest change of any byte: zero when the tile's bytes are as they were.
      if (pop == 0) {
        settled = allRows;
      } else {
        ++changes_[static_cast<std::size_t>(ty) * tilesX_ + tx];
      }
      r.pop = std::max(r.pop, pop);
      ++r.tilesBlended;
    }
  }
  return r;
}

}  // namespace vbim::gs
