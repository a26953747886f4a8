#include "gs/scripted_source.hpp"

#include <algorithm>

#include "gs/error.hpp"

namespace vbim::gs {

ScriptedFrameSource::ScriptedFrameSource(std::vector<StreamInfo> streams, ImageFn image, SourceScript script)
    : streams_(std::move(streams)), image_(std::move(image)), script_(std::move(script)) {
  if (streams_.empty()) throw GsError("a frame source needs at least one stream");
  for (const StreamInfo& s : streams_) {
    if (s.frameCount <= 0 || s.fpsNum <= 0 || s.fpsDen <= 0) {
      throw GsError("stream '" + s.name + "' needs a positive frame count and frame rate");
    }
  }
}

int ScriptedFrameSource::variantFor(std::int64_t seq) const {
  auto it = branches_.upper_bound(seq);
  return it == branches_.begin() ? 0 : std::prev(it)->second;
}

Tick ScriptedFrameSource::pushPastStalls(Tick t) const {
  for (bool moved = true; moved;) {
    moved = false;
    for (const Stall& s : script_.stalls) {
      if (t >= s.begin && t < s.begin + s.duration) {
        t = s.begin + s.duration;
        moved = true;
      }
    }
  }
  return t;
}

Tick ScriptedFrameSource::readyTime(std::int64_t seq) {
  while (static_cast<std::int64_t>(ready_.size()) <= seq) {
    const auto k = static_cast<std::int64_t>(ready_.size());
    Tick t = std::max<Tick>(dueTime(streams_[0], script_.t0, k) - script_.lead, 0);
    if (k > 0) t = std::max(t, ready_.back() + script_.decodeTime);
    auto b = branchAt_.upper_bound(k);  // the latest branch that starts at or before k
    if (b != branchAt_.begin()) {
      --b;
      t = std::max(t, b->second + script_.branchLatency + (k - b->first) * script_.decodeTime);
    }
    ready_.push_back(pushPastStalls(t));
  }
  return ready_[static_cast<std::size_t>(seq)];
}

std::optional<ReadyFrame> ScriptedFrameSource::newestReady(std::int64_t maxSeq, Tick now) {
  if (!script_.loop) maxSeq = std::min(maxSeq, streams_[0].frameCount - 1);
  if (maxSeq < 0 || readyTime(0) > now) return std::nullopt;
  readyTime(maxSeq);
  // Ready times never decrease: binary search for the newest one at or before now.
  const auto end = ready_.begin() + maxSeq + 1;
  const std::int64_t seq = (std::upper_bound(ready_.begin(), end, now) - ready_.begin()) - 1;
  const int variant = variantFor(seq);
  if (!cached_ || cache_.seq != seq || cache_.variant != variant) {
    const StreamInfo& info = streams_[static_cast<std::size_t>(variant)];
    cache_ = ReadyFrame{variant, seq, ready_[static_cast<std::size_t>(seq)],
                        std::make_shared<const Rgba8Image>(image_(variant, streamFrameOf(info, seq)))};
    cached_ = true;
    ++framesMade_;
  }
  return cache_;
}

void ScriptedFrameSource::branch(int variant, std::int64_t fromSeq, Tick now) {
  if (variant < 0 || variant >= static_cast<int>(streams_.size())) {
    throw GsError("branch to stream " + std::to_string(variant) + ", but the source has " +
                  std::to_string(streams_.size()) + " streams");
  }
  branches_[fromSeq] = variant;
  branchAt_[fromSeq] = now;
  // Ready times from fromSeq on depend on the seek: recompute them.
  if (static_cast<std::int64_t>(ready_.size()) > fromSeq) ready_.resize(static_cast<std::size_t>(fromSeq));
  cached_ = false;
}

}  // namespace vbim::gs
