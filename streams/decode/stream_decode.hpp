// Every picture of a stream file through the IPU decoder, without timing: the body of `vbim decode`.
// The file may be a program stream (a VBIM stream, ffmpeg's MPEG-2 program streams and MPEG-1 system
// streams) or a raw MPEG-1/2 video elementary stream; streams/video_elementary_stream.hpp takes the
// video out of it and the IPU model (ipu/) decodes it. Frames go to a sink (frame_files.hpp writes
// them as files); diagnostics go to a second sink, one line each, so nothing here prints.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ipu/picture_decoder.hpp"
#include "runtime/error.hpp"
#include "streams/stream_error.hpp"

namespace vbim::streams {

struct DecodeOptions {
  std::optional<std::uint8_t> streamId;    // PES id of the video stream; default: the first one
  unsigned threads = 0;                    // > 1: slice-parallel decode on this many host threads (same bytes)
  ipu::IdctKind idct = ipu::kDefaultIdct;  // the inverse DCT (platform parameter ipu.idct)
};

// An issue the decoder reported, placed in the file: what a script needs to find the damage.
struct LocatedIssue {
  ipu::IssueKind kind{};
  std::uint64_t fileOffset = 0;  // the file byte where the decoder found it
  int mbX = -1;                  // macroblock column and row (the slice's row), -1 when not tied to one
  int mbY = -1;
};

// A picture that was concealed in part or could not be decoded at all (skipped).
struct DamagedPicture {
  int picture = 0;               // in coding (file) order, from 0, counting every picture of the stream
  int frame = -1;                // the frame number it was written as (display order), -1: none (skipped, or
                                 // a frame never shown)
  int codingType = 0;            // 1 I, 2 P, 3 B, 4 D; 0 when its header could not be read
  std::uint64_t fileOffset = 0;  // where its bytes (the headers before it included) begin in the file
  bool skipped = false;          // undecodable: no frame of its own
  std::size_t issueCount = 0;    // all of them; `issues` keeps the first ipu::PictureReport::kMaxIssues
  int macroblocks = 0;
  int macroblocksConcealed = 0;
  std::vector<LocatedIssue> issues;
};

struct DecodeSummary {
  int pictures = 0;  // in the stream (access units), skipped ones included
  int frames = 0;
  int width = 0;
  int height = 0;
  bool mpeg2 = false;
  std::optional<std::uint8_t> streamId;  // the PES id of the video stream of a program stream
  std::string streamLabel;               // " (video stream 0xE0)" for a program stream, empty otherwise
  std::size_t issues = 0;                // decode issues over all pictures
  long concealedMacroblocks = 0;
  int skippedPictures = 0;                    // pictures the decoder could not use at all (each an issue; no frame)
  std::vector<StreamError> containerDefects;  // skipped in the program stream (said as warnings)
  std::vector<DamagedPicture> damaged;        // in coding order
};

// Called with each frame in display order (numbered from 0) while the decoder holds it as its
// displayFrame(). A field picture completes its frame only with the second field, of the other parity.
using FrameSink = std::function<void(int frame, const ipu::Decoder& decoder)>;
// Called with one line per diagnostic: defects skipped in the container ("warning: ..."), issues
// found while decoding (with their file byte offset and macroblock).
using DiagnosticSink = std::function<void(const std::string& line)>;

// Decodes every picture of `file` (named `name` in messages). A picture the decoder cannot use (its
// header damaged, or a format it does not decode) is reported, skipped and counted. Throws Error
// when the file is not an MPEG stream, holds no such video stream, or no picture could be decoded.
DecodeSummary decodeStream(std::span<const std::uint8_t> file, const std::string& name, const DecodeOptions& options,
                           const FrameSink& frames, const DiagnosticSink& diagnostics);

}  // namespace vbim::streams
