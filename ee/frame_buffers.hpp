// The EE RAM buffers between the stages, per stream: the compressed frame buffer (complete pictures
// from the demux, waiting for the IPU) and the decoded frame buffers (IPU output, waiting for the
// GS). Both are bounded: a full buffer blocks its producer (exact back-pressure on the simulated
// clock), and both can drop everything from a sequence number on (a branch invalidates frames
// already loaded for the old variant).
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "gs/frame_source.hpp"
#include "runtime/event.hpp"
#include "runtime/image.hpp"
#include "streams/picture_header.hpp"

namespace vbim::ee {

struct CompressedPicture {
  std::int64_t seq = 0;  // the seq it is shown at (a picture decoded only as a reference: its run's seq for it)
  std::int64_t globalFrame = 0;
  bool damaged = false;  // disagreed with the descriptor index: the IPU conceals what it cannot decode
  std::vector<std::uint8_t> data;
  // Decode order (ee/decode_order.hpp): the key the demux and the IPU feeder order pictures by
  // (the seq itself in an intra-only stream), whether the picture is shown (a branch into the middle
  // of a GOP decodes its references from the GOP's I picture without showing them), its type, and
  // whether a picture of this stream before it in decode order was lost (its references may be).
  std::int64_t key = 0;
  bool shown = true;
  streams::PictureType type = streams::PictureType::I;
  bool afterLoss = false;
};

class CompressedBuffer {
 public:
  CompressedBuffer(Scheduler& s, std::size_t depth) : depth_(depth), room_(s), filled_(s) {}
  bool full() const { return q_.size() >= depth_; }
  bool empty() const { return q_.empty(); }
  std::size_t size() const { return q_.size(); }
  const CompressedPicture& front() const { return q_.front(); }
  void push(CompressedPicture p) {
    bytes_ += p.data.size();
    q_.push_back(std::move(p));
    filled_.notify();
  }
  CompressedPicture pop() {
    CompressedPicture p = std::move(q_.front());
    q_.pop_front();
    bytes_ -= p.data.size();
    room_.notify();
    return p;
  }
  // Drops every picture with key >= from (in key order: the last ones).
  void dropFrom(std::int64_t from) {
    while (!q_.empty() && q_.back().key >= from) {
      bytes_ -= q_.back().data.size();
      q_.pop_back();
    }
    room_.notify();
  }
  std::size_t bytes() const { return bytes_; }  // of the pictures held
  Event& room() { return room_; }
  Event& filled() { return filled_; }

 private:
  std::size_t depth_;
  std::size_t bytes_ = 0;
  std::deque<CompressedPicture> q_;
  Event room_;
  Event filled_;
};

// Decoded frames of one stream; the GS presenter reads them through gs::FrameSource.
class DecodedFrames final : public gs::FrameSource {
 public:
  // `owner` receives branch() calls (the pipeline: it repositions the demux for both streams).
  class BranchSink {
   public:
    virtual ~BranchSink() = default;
    virtual void onBranch(int variant, std::int64_t fromSeq, Tick now) = 0;
  };

  DecodedFrames(Scheduler& s, std::vector<gs::StreamInfo> streams, std::size_t depth, BranchSink& owner)
      : streams_(std::move(streams)), depth_(depth), owner_(owner), room_(s) {}

  const std::vector<gs::StreamInfo>& streams() const override { return streams_; }
  std::optional<gs::ReadyFrame> newestReady(std::int64_t maxSeq, Tick now) override {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < q_.size(); ++i) {
      if (q_[i].seq <= maxSeq && q_[i].readyAt <= now) best = i;
    }
    if (!best) return std::nullopt;
    if (*best > 0) {
      q_.erase(q_.begin(), q_.begin() + static_cast<std::ptrdiff_t>(*best));  // older ones are never shown now
      room_.notify();
    }
    return q_.front();
  }
  void branch(int variant, std::int64_t fromSeq, Tick now) override { owner_.onBranch(variant, fromSeq, now); }

  bool full() const { return q_.size() >= depth_; }
  void push(gs::ReadyFrame f) { q_.push_back(std::move(f)); }
  void dropFrom(std::int64_t from) {
    while (!q_.empty() && q_.back().seq >= from) q_.pop_back();
    room_.notify();
  }
  Event& room() { return room_; }
  std::size_t size() const { return q_.size(); }

 private:
  std::vector<gs::StreamInfo> streams_;
  std::size_t depth_;
  BranchSink& owner_;
  std::deque<gs::ReadyFrame> q_;
  Event room_;
};

}  // namespace vbim::ee
