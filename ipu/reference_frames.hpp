// The decoder's frame memory for prediction (ISO/IEC 13818-2 §7.6) and display order (§6.1.1.11):
// three frame stores whose roles rotate, so that no frame is ever copied. At any time one is the
// frame being decoded (`current`), up to two hold the forward and backward reference frames (the
// two I or P frames decoded last), and one frame may be due for display.
//
// Display order: a B frame is shown as soon as it is decoded; an I or P frame is held back and
// shown when the next I or P frame is complete (or at the end of the stream, flush()). An I or P
// frame is decoded into the store of the older reference, which it replaces, a B frame into the
// store that holds neither reference. A frame whose store held another picture keeps that
// picture's samples wherever no slice reached: the decoder then copies those macroblocks from
// previous() (ipu/picture_decoder.cpp), so concealment shows the picture decoded before.
#pragma once

#include <array>

#include "ipu/frame_store.hpp"

namespace vbim::ipu {

class FrameBuffers {
 public:
  // A frame (or its first field) of picture_coding_type `codingType` (1 I, 2 P, 3 B) begins: picks
  // its store, resized (and mid-grey) when it has another size, or always mid-grey with `fresh`.
  FrameStore& begin(int codingType, int mbWidth, int mbHeight, bool fresh);
  // The frame begun last is complete (both fields of a field-picture frame): it becomes a reference
  // if it is an I or P frame, and the frame due for display is updated.
  void complete(int codingType, int width, int height);

  FrameStore& current() { return stores_[cur_]; }
  const FrameStore& current() const { return stores_[cur_]; }
  // The reference frames for the picture being decoded, null when there is none (or its size
  // differs from the current frame's): for a P picture its reference is backward(), the I or P
  // frame decoded last; a B picture predicts from forward() (older) and backward().
  const FrameStore* forward() const { return usable(fwd_); }
  const FrameStore* backward() const { return usable(bwd_); }
  // The store decoded into before the current frame began (the previous picture), null if none or
  // if it is the current store.
  const FrameStore* previous() const { return prev_ >= 0 && prev_ != cur_ ? usable(prev_) : nullptr; }

  // The frame due for display after the last complete(), null if none (a first I or P frame waits).
  const FrameStore* display() const { return display_ >= 0 ? &stores_[display_] : nullptr; }
  int displayWidth() const { return display_ >= 0 ? size_[display_][0] : 0; }
  int displayHeight() const { return display_ >= 0 ? size_[display_][1] : 0; }
  // End of the stream: the newest reference frame becomes the frame due for display if it was not
  // shown yet. False if there is none.
  bool flush();
  void clearDisplay() { display_ = -1; }
  // Forgets the references and what is due (a sequence of another size begins, or the caller starts over).
  void dropReferences();

 private:
  const FrameStore* usable(int i) const {
    if (i < 0) return nullptr;
    const FrameStore& s = stores_[i];
    const FrameStore& c = stores_[cur_];
    return s.mbWidth == c.mbWidth && s.mbHeight == c.mbHeight ? &s : nullptr;
  }

  std::array<FrameStore, 3> stores_;
  std::array<std::array<int, 2>, 3> size_{};  // display width and height of the frame each store holds
  int cur_ = 0;
  int fwd_ = -1;
  int bwd_ = -1;
  int prev_ = -1;
  int display_ = -1;
  bool bwdShown_ = true;  // the backward reference was already displayed (or there is none)
};

}  // namespace vbim::ipu
