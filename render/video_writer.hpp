// The playback as a video file through libavcodec: MPEG-4 Part 2 in an MP4 container (plays
// everywhere; the project's MPEG-2 path is for the PS2 stream itself). Fixed quantiser; frames are
// taken one at a time; written under a temporary name by the caller's OutputDir.
#pragma once

#include <filesystem>
#include <memory>

#include "runtime/image.hpp"

namespace vbim::render {

class VideoWriter {
 public:
  // width and height must be even. Throws RenderError naming the file.
  VideoWriter(const std::filesystem::path& path, int width, int height, int fps, int quantiser = 4);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void add(const Rgba8Image& frame);
  // Flushes the encoder and writes the trailer; the file is complete after this.
  void finish();
  std::int64_t frames() const;

 private:
  struct Av;
  std::unique_ptr<Av> av_;
};

}  // namespace vbim::render
