// The playback as a video file through libavcodec: MPEG-4 Part 2 in an MP4 container (plays
// everywhere; the project's MPEG-2 path is for the PS2 stream itself). Fixed quantiser; frames are
// taken one at a time; written under a temporary name by the caller's OutputDir.
//
// Timing: the video's clock counts in 1/fps s and each frame carries its start and duration on it,
// so a run's saved frames can play at the run's speed (videoSlots): 60 s of simulated time play in
// 60 s however few frames were saved, each frame held until the next one was saved.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "runtime/image.hpp"

namespace vbim::render {

// Where a frame lies on the video's clock, in ticks of 1/fps s.
struct VideoSlot {
  bool shown = false;  // false: it falls on the tick of the frame before and is left out
  std::int64_t pts = 0;
  std::int64_t duration = 0;
};

// The slots of frames saved at simulated times `startS` (ascending, seconds) in a run that ends at
// `endS`, on a clock of `fps` ticks per second starting at startS[0]: each shown frame lasts until
// the next shown one starts, the last until endS (at least one tick). A frame that rounds to the
// tick of the one before is not shown (the video cannot show both at this rate). Throws
// RenderError for times out of order or an end before the last frame.
std::vector<VideoSlot> videoSlots(const std::vector<double>& startS, double endS, int fps);

class VideoWriter {
 public:
  // width and height must be even. Throws RenderError naming the file.
  VideoWriter(const std::filesystem::path& path, int width, int height, int fps, int quantiser = 4);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The next frame, from `pts` for `duration` ticks of 1/fps s (pts after the previous frame's).
  void add(const Rgba8Image& frame, std::int64_t pts, std::int64_t duration);
  // Flushes the encoder and writes the trailer; the file is complete after this.
  void finish();
  std::int64_t frames() const;

 private:
  struct Av;
  std::unique_ptr<Av> av_;
};

}  // namespace vbim::render
