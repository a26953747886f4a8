// The decoder's picture memory: YCbCr 4:2:0 planes padded to whole macroblocks. It persists from
// picture to picture, so a macroblock that cannot be decoded keeps its previous value; a new
// store starts mid-grey (Y = Cb = Cr = 128).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vbim::ipu {

struct FrameStore {
  int mbWidth = 0;
  int mbHeight = 0;  // macroblock rows of the frame
  int lumaStride = 0;
  int chromaStride = 0;
  std::vector<std::uint8_t> y, cb, cr;

  void reset(int mbw, int mbh) {
    mbWidth = mbw;
    mbHeight = mbh;
    lumaStride = mbw * 16;
    chromaStride = mbw * 8;
    y.assign(static_cast<std::size_t>(lumaStride) * mbh * 16, 128);
    cb.assign(static_cast<std::size_t>(chromaStride) * mbh * 8, 128);
    cr.assign(static_cast<std::size_t>(chromaStride) * mbh * 8, 128);
  }
  bool empty() const { return mbWidth == 0; }
};

}  // namespace vbim::ipu
