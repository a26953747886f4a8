// One macroblock of a P or B picture as the bitstream describes it (ISO/IEC 13818-2 §6.2.5,
// §6.3.17): the result of parsing, before anything is predicted or reconstructed. On the console
// the IPU parses (VDEC/BDEC: modes, vectors, coded block pattern, coefficients) and the EE forms
// the prediction and adds the residual; keeping the two steps apart lets a timed model drive them
// macroblock by macroblock and cost each.
#pragma once

#include <cstdint>

namespace vbim::ipu {

// Where a prediction reads from.
enum class PredictionRef : std::uint8_t {
  kForward,   // the forward reference frame (the I or P frame decoded last, for a P picture)
  kBackward,  // the backward reference frame (B pictures)
  kCurrent,   // the other field of the frame being decoded (the second field of a P frame, §7.6.3.5)
};

// One block prediction (§7.6.4): the macroblock's luma rows [top, top + height) of the destination
// (with dstField >= 0, of that field of a frame macroblock: 8 rows) are predicted from the reference
// displaced by the vector (half samples; vertical in the source's own lines, field lines for field
// prediction), or averaged with what earlier predictions of the macroblock wrote (§7.6.7). Chroma
// follows with the vector halved toward zero (§7.6.3.7).
struct PredictionOp {
  PredictionRef ref = PredictionRef::kForward;
  std::int8_t srcField = -1;  // -1: the reference frame; 0 / 1: its top / bottom field
  std::int8_t dstField =
      -1;                // -1: the macroblock in the picture; 0 / 1: the top / bottom field rows of a frame macroblock
  std::uint8_t top = 0;  // 0, or 8 for the lower half of 16x8 prediction
  std::uint8_t height = 16;  // luma rows: 16, or 8 (16x8 halves and field prediction in frame pictures)
  bool average = false;
  std::int16_t mvx = 0;
  std::int16_t mvy = 0;
};

struct Macroblock {
  int mbX = 0;  // column and row in the picture (a field picture's rows)
  int mbY = 0;
  std::uint8_t type = 0;  // kMb* flags of ipu/inter_vlc.hpp
  bool skipped = false;
  bool fieldDct = false;
  int opCount = 0;  // predictions, in order (none for an intra macroblock)
  PredictionOp ops[4];
  std::uint8_t pattern = 0;  // blocks with coefficients: bit 5 = block 0 (Y top left) .. bit 0 = block 5 (Cr)
  // Dequantised, saturated coefficients (raster order) with mismatch control applied; zero where
  // the block is not coded.
  alignas(32) std::int16_t block[6][64];
  // Each coded block's rows and columns that may hold a non-zero coefficient, with the flags
  // kIdctToggleOnly and kIdctFirstOnly in rowMask: the masks of the IDCT kernels (ipu/kernels.hpp).
  std::uint16_t rowMask[6] = {};
  std::uint8_t colMask[6] = {};
};

}  // namespace vbim::ipu
