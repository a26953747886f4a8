// The slice and macroblock layers of an intra picture (ISO/IEC 13818-2 §6.2.4-6.2.6, §7.2-7.5):
// macroblock addressing, macroblock modes, DC prediction, AC run/level VLC, inverse quantisation
// with saturation and mismatch control, the inverse DCT and the store into the frame. This is what
// the IPU's IDEC command does for one slice (docs/hardware.md#idec: DC prediction resets at slice start and
// on skipped-macroblock increments; per-macroblock quantiser_scale_code updates are honoured).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ipu/decode_report.hpp"
#include "ipu/kernels.hpp"

namespace vbim::ipu {

// Everything a slice needs that is fixed for the picture.
struct PictureParams {
  bool mpeg1 = false;
  IdctFn idct = nullptr;        // intra blocks: the chosen IdctKind's kernel (scalarKernels() or simdKernels())
  IdctAddFn idctAdd = nullptr;  // non-intra blocks: residual added to the prediction, same kind
  int mbWidth = 0;
  int mbRows = 0;            // macroblock rows of this picture (a field picture has half the frame's)
  bool tallPicture = false;  // vertical_size > 2800: slices carry slice_vertical_position_extension
  const std::uint8_t* scan = nullptr;
  std::array<std::uint8_t, 64> intraMatrix{};  // raster order
  int intraDcPrecision = 0;                    // 0..3
  bool qScaleType = false;
  bool intraVlcFormat = false;
  bool fieldDctAllowed = false;  // frame picture with frame_pred_frame_dct = 0: dct_type present
  bool concealmentMotionVectors = false;
  bool fieldPicture = false;
  int fCode[2] = {1, 1};  // forward f_code (horizontal, vertical) for concealment vectors
  // Destination lines of this picture (a field picture starts on its field's first line and steps
  // two frame lines).
  std::uint8_t* y = nullptr;
  std::uint8_t* cb = nullptr;
  std::uint8_t* cr = nullptr;
  int yStride = 0;
  int cStride = 0;
};

// Where each decoded macroblock's bits ended, for the timing model.
struct MacroblockBits {
  std::uint32_t address;    // mbRow * mbWidth + mbColumn within the picture
  std::uint32_t bits;       // bits of this macroblock (the first of a slice includes the slice header)
  std::uint32_t endByte;    // offset in the decoded bytes just past its last bit (rounded up)
  bool sliceStart = false;  // the first macroblock its slice decoded: IDEC was (re)issued for it
  // P and B pictures only (ipu/inter_slice_decoder.cpp), for the timed BDEC flow (ipu/mc_flow.hpp):
  // what the EE reads of this macroblock with VDEC (address increment and its escapes, macroblock
  // type, motion codes, dmvectors) and FDEC (motion type, DCT type, quantiser scale, field selects,
  // motion residuals, marker bit), what BDEC reads (blockBits: coded block pattern and blocks, 0
  // without BDEC), its block predictions and how many of them average, and the skipped
  // macroblocks just before it (each predicted like the macroblock before it, skippedPredictions).
  std::uint8_t vdec = 0;
  std::uint8_t fdec = 0;
  std::uint8_t predictions = 0;
  std::uint8_t averaged = 0;
  bool bdec = false;
  std::uint8_t skippedPredictions = 0;
  std::uint16_t skippedBefore = 0;
  std::uint32_t blockBits = 0;
};

struct SliceOutput {
  PictureReport* report = nullptr;
  std::vector<std::uint8_t>* decoded = nullptr;  // per picture macroblock: 1 once decoded
  int decodedStride = 0;                         // flags per macroblock row in `decoded`
  std::vector<MacroblockBits>* trace = nullptr;  // optional
};

// Decodes one slice: `code` is its start code value (1..0xAF); [begin, end) are the bytes after the
// start code up to the next start code; `offset` is begin's position in the caller's input (for
// reports). Never reads outside [begin, end) and always terminates.
void decodeSlice(const PictureParams& pp, int code, const std::uint8_t* begin, const std::uint8_t* end,
                 std::size_t offset, const SliceOutput& out);

// The row a slice starts on (slice_vertical_position - 1, without the extension).
inline int sliceRow(int code) {
  return code - 1;
}

}  // namespace vbim::ipu
