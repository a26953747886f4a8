// The playback timeline of one pipeline: sequence number k (counting from 0 across loop wraps, as the
// GS presenter does) -> the variant in force and the global frame of the stream file that k shows.
// Frames 0..F-1 play once; after frame F-1 playback continues at the descriptor's loop frame L, so
// seq k >= F shows frame L + (k - F) mod (F - L). Branches switch the variant from a seq on.
#pragma once

#include <cstdint>
#include <map>

#include "streams/descriptor.hpp"

namespace vbim::ee {

class Timeline {
 public:
  explicit Timeline(const streams::Descriptor& d)
      : frames_(d.framesPerVariant), loop_(d.loopFrame), variants_(static_cast<int>(d.variants.size())) {}

  // Frame within its variant (0..F-1) that seq k shows.
  std::int64_t frameInVariant(std::int64_t k) const {
    if (k < frames_) return k;
    return loop_ + (k - frames_) % (frames_ - loop_);
  }
  int variantOf(std::int64_t k) const {
    auto it = branches_.upper_bound(k);
    return it == branches_.begin() ? 0 : std::prev(it)->second;
  }
  // Global frame (v * F + f) of seq k.
  std::int64_t globalFrame(std::int64_t k) const { return variantOf(k) * frames_ + frameInVariant(k); }
  // True when seq k's frame follows seq k - 1's in the file (same variant, no wrap).
  bool followsInFile(std::int64_t k) const {
    return k == 0 ? variantOf(0) == 0 : globalFrame(k) == globalFrame(k - 1) + 1;
  }
  // The last seq >= k before the next loop wrap (the seq that shows frame F - 1).
  std::int64_t lapEnd(std::int64_t k) const {
    if (k < frames_) return frames_ - 1;
    const std::int64_t m = (k - frames_) % (frames_ - loop_);
    return k + (frames_ - loop_ - 1 - m);
  }
  // The first seq of the lap k is in (0, or the seq that shows the loop frame after a wrap).
  std::int64_t lapStart(std::int64_t k) const {
    if (k < frames_) return 0;
    return k - (k - frames_) % (frames_ - loop_);
  }
  // From seq `from` on, play `variant` (drops later branches: the newest decision wins).
  void branch(std::int64_t from, int variant) {
    branches_.erase(branches_.lower_bound(from), branches_.end());
    branches_[from] = variant;
  }
  std::int64_t framesPerVariant() const { return frames_; }
  int variants() const { return variants_; }

 private:
  std::int64_t frames_;
  std::int64_t loop_;
  int variants_;
  std::map<std::int64_t, int> branches_;
};

}  // namespace vbim::ee
