// A FrameSource driven by a script instead of a disc: frames come from a function, and become ready
// on a schedule: frame k is ready `lead` ticks before it is due, but no sooner than `decodeTime`
// after the previous one; nothing becomes ready inside a stall window, and frames held up by a
// stall then arrive one `decodeTime` apart (the catch-up burst). A branch makes the new variant's
// frames wait `branchLatency` (the seek) first.
//
// With no stalls and lead = 0 it is the stall-free reference: every frame ready exactly when due.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "gs/frame_source.hpp"

namespace vbim::gs {

struct Stall {
  Tick begin;
  Tick duration;
};

struct SourceScript {
  Tick t0 = 0;                // when seq 0 is due (the presenter's stream start)
  Tick lead = 0;              // frames are ready this long before they are due
  Tick decodeTime = 0;        // minimum spacing between ready times
  Tick branchLatency = 0;     // seek time before the first frame of a new variant
  std::vector<Stall> stalls;  // no frame becomes ready inside [begin, begin + duration)
  bool loop = true;           // seq wraps to stream frame seq % frameCount; else the stream ends
};

class ScriptedFrameSource : public FrameSource {
 public:
  // image(variant, streamFrame) makes a frame's pixels; called once per frame shown.
  using ImageFn = std::function<Rgba8Image(int variant, std::int64_t streamFrame)>;

  ScriptedFrameSource(std::vector<StreamInfo> streams, ImageFn image, SourceScript script);

  const std::vector<StreamInfo>& streams() const override { return streams_; }
  std::optional<ReadyFrame> newestReady(std::int64_t maxSeq, Tick now) override;
  void branch(int variant, std::int64_t fromSeq, Tick now) override;

  // When frame `seq` becomes ready under the script (for tests and the lag arithmetic).
  Tick readyTime(std::int64_t seq);
  std::int64_t framesMade() const { return framesMade_; }

 private:
  int variantFor(std::int64_t seq) const;
  Tick pushPastStalls(Tick t) const;

  std::vector<StreamInfo> streams_;
  ImageFn image_;
  SourceScript script_;
  std::vector<Tick> ready_;                // ready time of each seq computed so far
  std::map<std::int64_t, int> branches_;   // fromSeq -> variant
  std::map<std::int64_t, Tick> branchAt_;  // fromSeq -> time of the branch call
  std::int64_t framesMade_ = 0;
  ReadyFrame cache_;
  bool cached_ = false;
};

}  // namespace vbim::gs
