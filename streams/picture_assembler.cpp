#include "streams/picture_assembler.hpp"

#include <algorithm>

#include "streams/format.hpp"

namespace vbim::streams {

namespace {
bool startsAccessUnit(std::uint8_t code) {
  return code == kSequenceHeaderCode || code == kGroupStartCode || code == kPictureStartCode;
}
}  // namespace

bool PictureAssembler::append(std::span<const std::uint8_t> payload, std::uint32_t sector, std::uint64_t byteOffset,
                              std::optional<std::int64_t> pts, std::vector<Picture>& out) {
  if (payload.empty()) return true;
  segments_.push_back(Segment{static_cast<std::int64_t>(buf_.size()), sector, byteOffset, pts});
  buf_.insert(buf_.end(), payload.begin(), payload.end());
  std::size_t i = scanFrom_;
  while (i + 3 < buf_.size()) {
    // A start code 00 00 01 at i, i + 1 or i + 2 needs byte i + 2 to be 0 or 1: any other value
    // rules out all three (coded data is mostly such bytes, so the scan moves 3 bytes a step).
    const std::uint8_t third = buf_[i + 2];
    if (third > 1) {
      i += 3;
    } else if (third == 1 && buf_[i] == 0 && buf_[i + 1] == 0) {
      const std::size_t before = buf_.size();
      onStartCode(i, buf_[i + 3], out);
      i -= before - buf_.size();  // onStartCode may have removed bytes before i
      i += 4;
    } else {
      ++i;
    }
  }
  scanFrom_ = i;
  if (!synced_ && buf_.size() > 3) drop(buf_.size() - 3);  // keep only what may begin a start code
  if (buf_.size() > kMaxPictureBytes) {
    reset();
    return false;
  }
  return true;
}

// PTS: ISO/IEC 13818-1 §2.4.3.7 gives a PES packet's PTS to the first picture whose picture start
// code commences in it; libavformat's MPEG-PS muxer (which writes our streams) gives it to the first
// access unit whose first byte (the sequence header) commences in it. The two disagree when several
// small pictures share a packet, so we follow the muxer that wrote the file. Players identify frames
// by position through the descriptor index, not by PTS.
void PictureAssembler::onStartCode(std::size_t pos, std::uint8_t code, std::vector<Picture>& out) {
  if (!synced_) {
    // (Re)start only at a sequence header: a picture cannot be decoded without the one before it, and
    // after a seek the bytes before the indexed sequence header are the previous picture's tail.
    if (code != kSequenceHeaderCode) return;
    drop(pos);
    synced_ = true;
    seenPicture_ = false;
    takePts(0);
  } else if (seenPicture_ && (startsAccessUnit(code) || code == kSequenceEndCode)) {
    emit(pos, out);
    if (code == kSequenceEndCode) {  // the end code belongs to no picture: resynchronise after it
      synced_ = false;
      return;
    }
    takePts(0);
  }
  if (code == kPictureStartCode) seenPicture_ = true;
}

void PictureAssembler::takePts(std::size_t pos) {
  Segment& s = segmentAt(pos);
  if (s.pts && !s.ptsUsed) {
    pts_ = s.pts;
    s.ptsUsed = true;
  }
}

PictureAssembler::Segment& PictureAssembler::segmentAt(std::size_t pos) {
  auto it = std::upper_bound(segments_.begin(), segments_.end(), static_cast<std::int64_t>(pos),
                             [](std::int64_t p, const Segment& s) { return p < s.pos; });
  return *(it - 1);  // segments_[0].pos <= 0 always holds while buf_ is not empty
}

void PictureAssembler::emit(std::size_t end, std::vector<Picture>& out) {
  Picture p;
  p.streamId = streamId_;
  const Segment& first = segmentAt(0);
  p.firstSector = first.sector;
  p.byteOffset = first.byteOffset + static_cast<std::uint64_t>(-first.pos);
  p.lastSector = segmentAt(end - 1).sector;
  p.pts = pts_;
  p.data.assign(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(end));
  out.push_back(std::move(p));
  pts_.reset();
  seenPicture_ = false;
  discarded_ -= end;  // drop() counts discarded bytes; these were delivered
  drop(end);
}

void PictureAssembler::drop(std::size_t count) {
  if (count == 0) return;
  buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(count));
  discarded_ += count;
  scanFrom_ = scanFrom_ > count ? scanFrom_ - count : 0;
  for (Segment& s : segments_) s.pos -= static_cast<std::int64_t>(count);
  // Keep the last segment that starts at or before the new position 0.
  auto firstKept = std::upper_bound(segments_.begin(), segments_.end(), std::int64_t{0},
                                    [](std::int64_t p, const Segment& s) { return p < s.pos; });
  if (firstKept != segments_.begin()) segments_.erase(segments_.begin(), firstKept - 1);
  if (buf_.empty()) segments_.clear();
}

bool PictureAssembler::reset() {
  const bool underway = synced_ && !buf_.empty();
  discarded_ += buf_.size();
  buf_.clear();
  segments_.clear();
  scanFrom_ = 0;
  synced_ = false;
  seenPicture_ = false;
  pts_.reset();
  return underway;
}

void PictureAssembler::finish(std::vector<Picture>& out) {
  if (synced_ && seenPicture_) emit(buf_.size(), out);
  reset();
}

}  // namespace vbim::streams
