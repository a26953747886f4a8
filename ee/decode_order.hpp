// The order a stream's pictures are decoded in, against the order they are shown. An MPEG-2 stream
// carries each I or P picture ahead of the B pictures shown before it (ISO/IEC 13818-2 §6.1.1.11),
// so the k-th picture decoded is not the k-th shown. The demux and the IPU feeder walk a stream in
// decode order, the GS shows it in display order; this class maps between the two, from the picture
// types of the descriptor's index (which is in display order, docs/stream-format.md).
//
// Ranks. Within a variant, rank(f) is the position of frame f's picture in decode order counted in
// display numbers: a B picture is decoded right after the reference that follows it, so
// rank(B at f) = f + 1; a reference is decoded right after the previous reference, so
// rank(I or P at f) = (previous reference) + 1 (0 for the first). Over any run of frames that starts
// at an I picture opening a GOP and ends at a reference, the ranks are a permutation of the run's
// frame numbers: the run's first picture takes the run's first number (its rank would be lower only
// through the leading B pictures of an open GOP, which are shown before it and so are not in the
// run). The writer makes every variant end on a reference and start, and loop, on a GOP-opening I
// (streams/authoring/stream_writer.cpp, Descriptor::validate), so a lap is such a run.
//
// For an intra-only stream every rank is its frame: decode order is display order.
#pragma once

#include <cstdint>
#include <vector>

#include "streams/descriptor.hpp"

namespace vbim::ee {

class DecodeOrder {
 public:
  DecodeOrder() = default;
  // Stream `s` (position in d.streams) of descriptor `d`.
  DecodeOrder(const streams::Descriptor& d, int s);

  bool intraOnly() const { return intraOnly_; }
  streams::PictureType type(std::int64_t globalFrame) const { return types_[static_cast<std::size_t>(globalFrame)]; }
  // Rank of frame f of variant v in a run that starts at frame `runStart` (a GOP-opening I, <= f).
  std::int64_t rank(int v, std::int64_t f, std::int64_t runStart) const;
  // The frame of variant v with rank r in a run that starts at `runStart` (r >= runStart).
  std::int64_t frameAtRank(int v, std::int64_t r, std::int64_t runStart) const;
  // The global frame whose picture comes next in the file after global frame g's (this stream), or -1.
  std::int64_t nextInFile(std::int64_t g) const { return nextInFile_[static_cast<std::size_t>(g)]; }
  // The frame of variant v at or before f where decoding must start to show f (Descriptor::resumeFrame).
  std::int64_t resumeFrame(int v, std::int64_t f) const;

 private:
  std::int64_t frames_ = 0;
  bool intraOnly_ = true;
  std::vector<streams::PictureType> types_;  // [global frame]
  std::vector<bool> gopStart_;               // [global frame]
  std::vector<std::int64_t> rank_;           // [global frame], within its variant
  std::vector<std::int64_t> byRank_;         // [variant * F + rank] -> frame in variant
  std::vector<std::int64_t> nextInFile_;     // [global frame]
};

}  // namespace vbim::ee
