// Frame sources for replaying a port's log (docs/porting.md, "Replay"):
//
// ArrivalSource plays an arrival schedule: "frame seq of stream variant arrived before vsync n".
// A frame that arrived for vsync n is ready at time(n - 1) + 1 (time(0) for n = 0): after the
// previous vsync, so at vsync n the presenter sees it, and it counts as late only if it was due at
// an earlier vsync. Branches need no seek: the schedule names each frame's variant.
//
// RecordingSource wraps another source and reports each frame the presenter receives from it the
// first time (its variant, seq and ready time), which is how `vbim play` writes arrivals.csv.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "gs/frame_source.hpp"
#include "runtime/vsync.hpp"

namespace vbim::gs {

struct Arrival {
  std::int64_t vsync = 0;  // the first vsync at which the frame may be shown
  int variant = 0;
  std::int64_t seq = 0;  // timeline sequence number (counts on across loop wraps)
};

class ArrivalSource : public FrameSource {
 public:
  // The picture of timeline frame `seq` of a variant: the caller maps seq to its stream frame (a
  // stream may loop to a frame other than 0, which StreamInfo does not know).
  using ImageFn = std::function<Rgba8Image(int variant, std::int64_t seq)>;
  // Throws GsError for a variant the streams do not have or a negative seq or vsync.
  ArrivalSource(std::vector<StreamInfo> streams, ImageFn image, VsyncClock clock, const std::vector<Arrival>& arrivals);

  const std::vector<StreamInfo>& streams() const override { return streams_; }
  std::optional<ReadyFrame> newestReady(std::int64_t maxSeq, Tick now) override;
  void branch(int, std::int64_t, Tick) override {}

 private:
  std::vector<StreamInfo> streams_;
  ImageFn image_;
  VsyncClock clock_;
  std::map<std::int64_t, std::vector<std::pair<Tick, int>>> bySeq_;  // seq -> (ready time, variant), by time
  ReadyFrame cache_;
  bool cached_ = false;
};

class RecordingSource : public FrameSource {
 public:
  using Hook = std::function<void(int variant, std::int64_t seq, Tick readyAt)>;
  RecordingSource(FrameSource& inner, Hook hook) : inner_(inner), hook_(std::move(hook)) {}

  const std::vector<StreamInfo>& streams() const override { return inner_.streams(); }
  std::optional<ReadyFrame> newestReady(std::int64_t maxSeq, Tick now) override {
    auto f = inner_.newestReady(maxSeq, now);
    if (f && (!last_ || f->seq != last_->first || f->variant != last_->second)) {
      last_ = {f->seq, f->variant};
      if (hook_) hook_(f->variant, f->seq, f->readyAt);
    }
    return f;
  }
  void branch(int variant, std::int64_t fromSeq, Tick now) override { inner_.branch(variant, fromSeq, now); }

 private:
  FrameSource& inner_;
  Hook hook_;
  std::optional<std::pair<std::int64_t, int>> last_;
};

// The first vsync at or after t: when a frame ready at t is first shown.
inline std::int64_t firstVsyncAtOrAfter(const VsyncClock& clock, Tick t) {
  if (t <= clock.time(0)) return 0;
  std::int64_t n = clock.countAt(t);
  if (clock.time(n) < t) ++n;
  return n;
}

}  // namespace vbim::gs
