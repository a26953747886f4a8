// One video stream's elementary-stream bytes out of a stream file: taken from a program stream (any
// form ProgramStreamReader reads) or given as a raw MPEG-1/2 video elementary stream (.m1v, .m2v),
// with where each byte lies in the file, so that a decoder's byte offsets can be reported as file
// offsets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "streams/stream_error.hpp"

namespace vbim::streams {

// What a file holds, judged by its first bytes.
enum class StreamForm {
  ProgramStream,     // starts with a pack start code 00 00 01 BA
  ElementaryStream,  // otherwise holds a start code 00 00 01 (the decoder judges the rest)
  NotMpeg,           // neither
};
StreamForm detectStreamForm(std::span<const std::uint8_t> file);

struct VideoElementaryStream {
  // A run of elementary-stream bytes that lie together in the file.
  struct Run {
    std::size_t esOffset;
    std::uint64_t fileOffset;
  };

  std::optional<std::uint8_t> streamId;  // PES stream id; none for a raw elementary stream, or when a
                                         // program stream lacks the video stream asked for
  std::vector<std::uint8_t> bytes;
  std::vector<Run> runs;             // ascending esOffset
  std::vector<StreamError> defects;  // damage skipped in the program stream

  // The file offset of elementary-stream byte `esOffset`.
  std::uint64_t fileOffsetOf(std::size_t esOffset) const;
};

// The payloads of video stream `streamId` (0xE0..0xEF), or of the first video stream when none is
// asked for, from a program stream.
VideoElementaryStream readVideoStream(std::span<const std::uint8_t> programStream,
                                      std::optional<std::uint8_t> streamId = std::nullopt);

// A raw video elementary stream as it is: one run from file byte 0.
VideoElementaryStream rawVideoStream(std::span<const std::uint8_t> file);

}  // namespace vbim::streams
