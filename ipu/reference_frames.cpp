#include "ipu/reference_frames.hpp"

namespace vbim::ipu {

FrameStore& FrameBuffers::begin(int codingType, int mbWidth, int mbHeight, bool fresh) {
  prev_ = stores_[cur_].empty() ? -1 : cur_;
  display_ = -1;
  int target = -1;
  if (codingType != 3 && fwd_ >= 0) {
    target = fwd_;  // replaced by this frame once it is complete; a P picture reads only bwd_
    fwd_ = -1;
  } else {
    // A store holding no reference; the current one if it can be (an intra-only stream keeps
    // decoding into one store, as the IPU does).
    for (int i : {cur_, (cur_ + 1) % 3, (cur_ + 2) % 3}) {
      if (i != fwd_ && i != bwd_) {
        target = i;
        break;
      }
    }
  }
  cur_ = target;
  FrameStore& s = stores_[cur_];
  if (fresh || s.mbWidth != mbWidth || s.mbHeight != mbHeight) s.reset(mbWidth, mbHeight);
  return s;
}

void FrameBuffers::complete(int codingType, int width, int height) {
  size_[cur_] = {width, height};
  if (codingType == 3) {
    display_ = cur_;
    return;
  }
  // An I or P frame: the previous backward reference is now due, and this frame waits.
  display_ = (bwd_ >= 0 && !bwdShown_) ? bwd_ : -1;
  fwd_ = bwd_;
  bwd_ = cur_;
  bwdShown_ = false;
}

bool FrameBuffers::flush() {
  display_ = -1;
  if (bwd_ < 0 || bwdShown_) return false;
  display_ = bwd_;
  bwdShown_ = true;
  return true;
}

void FrameBuffers::dropReferences() {
  fwd_ = bwd_ = -1;
  display_ = -1;
  bwdShown_ = true;
}

}  // namespace vbim::ipu
