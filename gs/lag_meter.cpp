#include "gs/lag_meter.hpp"

#include <algorithm>

#include "gs/error.hpp"

namespace vbim::gs {

LagSample compareImages(const Rgba8Image& a, const Rgba8Image& b, const BlendKernels& kernels) {
  if (!a.sameSize(b)) throw GsError("lag between lightmaps of different sizes");
  // One row of all the bytes: the rows of an image follow each other without padding.
  const ByteDifference d = kernels.compareRect(a.pixels.data(), 0, b.pixels.data(), 0, a.pixels.size(), 1);
  LagSample s;
  s.maxDiff = d.max;
  s.sumDiff = d.sum;
  return s;
}

TiledDifference::TiledDifference(const Presenter& run, const Presenter& reference, CompareRectFn compare,
                                 TwinTiles* equal)
    : run_(run),
      ref_(reference),
      compare_(compare),
      equal_(equal),
      tilesX_(run.blender().tilesX()),
      tilesY_(run.blender().tilesY()),
      tiles_(static_cast<std::size_t>(tilesX_) * tilesY_) {
  if (!run.lightmap().sameSize(reference.lightmap())) {
    throw GsError("lag between lightmaps of different sizes: " + std::to_string(run.lightmap().width) + "x" +
                  std::to_string(run.lightmap().height) + " and " + std::to_string(reference.lightmap().width) + "x" +
                  std::to_string(reference.lightmap().height));
  }
  if (equal_ != nullptr && equal_->size() != tiles_.size()) {
    throw GsError("lag: the equal-tile facts are for " + std::to_string(equal_->size()) +
                  " tiles, the lightmaps have " + std::to_string(tiles_.size()));
  }
}

ByteDifference TiledDifference::update() {
  const Rgba8Image& a = run_.lightmap();
  const Rgba8Image& b = ref_.lightmap();
  const std::vector<std::uint64_t>& runChanges = run_.blender().tileChanges();
  const std::vector<std::uint64_t>& refChanges = ref_.blender().tileChanges();
  const std::size_t stride = static_cast<std::size_t>(a.width) * 4;
  ByteDifference total;
  for (int ty = 0; ty < tilesY_; ++ty) {
    const int y0 = ty * kTileHeight;
    const auto rows = static_cast<std::size_t>(std::min(kTileHeight, a.height - y0));
    for (int tx = 0; tx < tilesX_; ++tx) {
      const std::size_t i = static_cast<std::size_t>(ty) * tilesX_ + tx;
      if (first_ || runChanges[i] != runSeen_[i] || refChanges[i] != refSeen_[i]) {
        if (equal_ != nullptr && equal_->equalAt(i, runChanges[i], refChanges[i])) {
          tiles_[i] = ByteDifference{};  // the same bytes: no difference
        } else {
          const std::size_t left = static_cast<std::size_t>(tx) * kTileWidth * 4;  // bytes into the row
          const std::size_t bytes = static_cast<std::size_t>(std::min(kTileWidth, a.width - tx * kTileWidth)) * 4;
          tiles_[i] = compare_(a.row(y0) + left, stride, b.row(y0) + left, stride, bytes, rows);
          if (equal_ != nullptr && tiles_[i].max == 0) equal_->setEqual(i, runChanges[i], refChanges[i]);
        }
      }
      total.max = std::max(total.max, tiles_[i].max);
      total.sum += tiles_[i].sum;
    }
  }
  runSeen_ = runChanges;
  refSeen_ = refChanges;
  first_ = false;
  return total;
}

LagMeter::LagMeter(Presenter& run, Presenter& reference, Tracer* tracer, const std::string& name)
    : run_(run), ref_(reference), tracer_(tracer) {
  if (tracer_ != nullptr && tracer_->enabled()) counter_ = tracer_->counter(name + ".lag");
}

Task<void> LagMeter::measure(Tick end) {
  const VsyncClock clock = run_.clock();
  for (std::int64_t n = 0; clock.time(n) < end; ++n) {
    while (run_.presented() <= n) co_await run_.presentedEvent().wait();
    while (ref_.presented() <= n) co_await ref_.presentedEvent().wait();
    LagSample s = compareImages(run_.lightmap(), ref_.lightmap());
    s.vsync = n;
    maxLag_ = std::max(maxLag_, s.maxDiff);
    samples_.push_back(s);
    if (tracer_ != nullptr && tracer_->enabled()) tracer_->value(counter_, run_.clock().time(n), s.maxDiff);
  }
}

}  // namespace vbim::gs
