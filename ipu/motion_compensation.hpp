// Motion-compensated reconstruction of one parsed macroblock (ISO/IEC 13818-2 §7.6): forming the
// predictions from the reference frames (§7.6.4; half-sample interpolation with (a + b + 1) >> 1
// and (a + b + c + d + 2) >> 2), combining them (§7.6.7, (p + q + 1) >> 1), and adding the inverse
// DCT of the coded blocks with the clip to 0..255 (§7.6.8). On the console this is the EE's share.
#pragma once

#include "ipu/decode_report.hpp"
#include "ipu/frame_store.hpp"
#include "ipu/macroblock.hpp"
#include "ipu/mc_kernels.hpp"
#include "ipu/slice_decoder.hpp"

namespace vbim::ipu {

// The frames predictions read: null where the stream gives none (a P picture after a lost I
// picture, a B picture at a stream start); `current` is the frame being decoded (field P pictures).
struct ReferenceSet {
  const FrameStore* forward = nullptr;
  const FrameStore* backward = nullptr;
  const FrameStore* current = nullptr;
};

struct PredictionResult {
  bool missingReference = false;  // a prediction had no reference frame: mid-grey was used
  bool clamped = false;           // a vector pointed outside the reference: moved to its edge
};

// Writes the prediction of `mb` (its ops) into the picture `pp` describes. Never reads outside a
// reference frame, whatever the vectors.
// `mc`: Kernels::mc of scalarKernels() or simdKernels() (ipu/kernels.hpp), the same bytes.
PredictionResult predictMacroblock(const Macroblock& mb, const ReferenceSet& refs, const PictureParams& pp,
                                   const McKernels& mc = scalarMcKernels());

// Adds the coded blocks' residuals to the prediction with the clip (non-intra), or writes the
// clipped inverse DCT of all six blocks (intra). Clears the coefficients it used.
void reconstructBlocks(Macroblock& mb, const PictureParams& pp);

}  // namespace vbim::ipu
