#include "gs/arrival_source.hpp"

#include <algorithm>

#include "gs/error.hpp"

namespace vbim::gs {

ArrivalSource::ArrivalSource(std::vector<StreamInfo> streams, ImageFn image, VsyncClock clock,
                             const std::vector<Arrival>& arrivals)
    : streams_(std::move(streams)), image_(std::move(image)), clock_(clock) {
  if (streams_.empty()) throw GsError("an arrival schedule needs at least one stream");
  for (const Arrival& a : arrivals) {
    if (a.variant < 0 || a.variant >= static_cast<int>(streams_.size())) {
      throw GsError("arrival at vsync " + std::to_string(a.vsync) + " names variant " + std::to_string(a.variant) +
                    ", but the stream has " + std::to_string(streams_.size()));
    }
    if (a.seq < 0 || a.vsync < 0) {
      throw GsError("arrival at vsync " + std::to_string(a.vsync) + " of frame " + std::to_string(a.seq) +
                    ": vsync and frame must not be negative");
    }
    const Tick ready = a.vsync == 0 ? clock_.time(0) : clock_.time(a.vsync - 1) + 1;
    bySeq_[a.seq].emplace_back(ready, a.variant);
  }
  for (auto& [seq, list] : bySeq_) {
    std::stable_sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  }
}

// The newest seq <= maxSeq with an arrival at or before now; of a seq's arrivals, the latest one.
std::optional<ReadyFrame> ArrivalSource::newestReady(std::int64_t maxSeq, Tick now) {
  for (auto it = bySeq_.upper_bound(maxSeq); it != bySeq_.begin();) {
    --it;
    const auto& list = it->second;
    auto last = std::upper_bound(list.begin(), list.end(), now, [](Tick t, const auto& e) { return t < e.first; });
    if (last == list.begin()) continue;
    --last;
    const std::int64_t seq = it->first;
    const int variant = last->second;
    if (!cached_ || cache_.seq != seq || cache_.variant != variant) {
      cache_ = ReadyFrame{variant, seq, last->first, std::make_shared<const Rgba8Image>(image_(variant, seq))};
      cached_ = true;
    }
    return cache_;
  }
  return std::nullopt;
}

}  // namespace vbim::gs
