// What the vsync presenter needs from the rest of the pipeline: decoded frames, each with its
// place in the playback timeline and the simulated time it became ready. The player (issue #7)
// implements it over the IPU's output; tests use ScriptedFrameSource.
//
// Sequence numbers count frames of the timeline from 0 and keep counting across loop wraps:
// sequence k shows stream frame k % frameCount and is due at t0 + k / fps. Frames become ready in
// sequence order (a decoder produces them in order).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/clock.hpp"
#include "runtime/image.hpp"

namespace vbim::gs {

// One stream the source can play: the lighting video and its variants (weather), all with the
// same frame size, rate and length so a branch can continue at the same time of day.
struct StreamInfo {
  std::string name;
  int width = 0;
  int height = 0;
  std::int64_t frameCount = 0;
  std::int64_t fpsNum = 1;  // frame rate fpsNum / fpsDen Hz
  std::int64_t fpsDen = 1;
};

struct ReadyFrame {
  int variant = 0;
  std::int64_t seq = 0;
  Tick readyAt = 0;
  std::shared_ptr<const Rgba8Image> image;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The streams, indexed by variant number. Must not be empty.
  virtual const std::vector<StreamInfo>& streams() const = 0;
  // The newest frame with seq <= maxSeq that is ready at `now`, from the variant in force for its
  // seq (see branch). Frames older than one returned may be discarded by the source.
  virtual std::optional<ReadyFrame> newestReady(std::int64_t maxSeq, Tick now) = 0;
  // From sequence number fromSeq on, play `variant`: the source seeks to it and decodes its frames
  // fromSeq, fromSeq + 1, ... (called at the branch time; variant is valid).
  virtual void branch(int variant, std::int64_t fromSeq, Tick now) = 0;
};

// The frame of the stream that sequence number seq shows (seq keeps counting across loops).
inline std::int64_t streamFrameOf(const StreamInfo& s, std::int64_t seq) {
  return seq % s.frameCount;
}

// Stream frame k of a stream is due at t0 + k * fpsDen / fpsNum, rounded down to a tick.
inline Tick dueTime(const StreamInfo& s, Tick t0, std::int64_t seq) {
  const __int128 p = static_cast<__int128>(seq) * kBusHz * s.fpsDen;
  return t0 + static_cast<Tick>(p / s.fpsNum);
}
// The largest seq due at or before t (-1 before t0).
inline std::int64_t dueSeq(const StreamInfo& s, Tick t0, Tick t) {
  if (t < t0) return -1;
  const __int128 q = static_cast<__int128>(t - t0) * s.fpsNum / (static_cast<__int128>(kBusHz) * s.fpsDen);
  std::int64_t k = static_cast<std::int64_t>(q);
  while (dueTime(s, t0, k + 1) <= t) ++k;
  while (k > 0 && dueTime(s, t0, k) > t) --k;
  return k;
}

}  // namespace vbim::gs
