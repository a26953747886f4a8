// The slice and macroblock layers of P and B pictures (ISO/IEC 13818-2 §6.2.4-6.2.6, §7.2-7.6;
// 11172-2 §2.4.2.7-2.4.4): macroblock addressing with skipped macroblocks (§7.6.6), the P and B
// macroblock modes, motion vectors with their predictors, coded block patterns, intra and
// non-intra blocks with their inverse quantisation (§7.4.2.3, and 11172-2's oddification), then
// prediction and reconstruction (ipu/motion_compensation.hpp). Each macroblock is first parsed
// whole into an ipu::Macroblock (the IPU's part on the console) and then reconstructed (the EE's).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ipu/motion_compensation.hpp"
#include "ipu/slice_decoder.hpp"

namespace vbim::ipu {

// Per scan position: the matrix weight at it, its raster index, and its row bit (bits 0-7) and column
// bit (bits 8-15) for the IDCT's masks; one lookup once the run is known.
struct InterScanSlot {
  std::uint8_t weight;
  std::uint8_t pos;
  std::uint16_t mask;
};
using InterScanSlots = std::array<std::array<InterScanSlot, 64>, 2>;  // [non-intra / intra]

// What a P or B picture adds to PictureParams.
struct InterParams {
  int codingType = 2;        // 2 P, 3 B
  int pictureStructure = 3;  // 1 top field, 2 bottom field, 3 frame
  bool framePredFrameDct = true;
  bool topFieldFirst = true;
  bool secondField = false;                       // the second field of a frame (P: may predict from the first)
  int fCode[2][2] = {{1, 1}, {1, 1}};             // [forward, backward][horizontal, vertical]
  bool fullPel[2] = {false, false};               // MPEG-1 full_pel_forward_vector / full_pel_backward_vector
  std::array<std::uint8_t, 64> nonIntraMatrix{};  // raster order
  ReferenceSet refs;
  const McKernels* mc = nullptr;  // null: scalarMcKernels()
  // From the scan and the two matrices, by prepareScanSlots() once the rest is set: built once per
  // picture instead of once per slice (~1 % of the decode of a 720x480 P or B picture).
  InterScanSlots scanSlots{};
};

// Fills ip.scanSlots from pp.scan, pp.intraMatrix and ip.nonIntraMatrix.
void prepareScanSlots(InterParams& ip, const PictureParams& pp);

// Decodes one slice of a P or B picture; the contract of decodeSlice() (ipu/slice_decoder.hpp).
// Macroblocks predicted from a missing reference count in report->macroblocksConcealed.
void decodeInterSlice(const PictureParams& pp, const InterParams& ip, int code, const std::uint8_t* begin,
                      const std::uint8_t* end, std::size_t offset, const SliceOutput& out);

}  // namespace vbim::ipu
