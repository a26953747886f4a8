// What the EE asks of the IPU for one picture of a motion-compensated stream, in the order the
// console's MPEG player does it (ps2sdk ee/mpeg/src/libmpeg.c and libmpeg_core.c @ 986ff320, the
// flow of Sony's libmpeg): every header field read with FDEC (VDEC for variable-length codes),
// quantiser matrices loaded with SETIQ, and per macroblock VDEC/FDEC for its modes and vectors,
// BDEC for its coded blocks (48 qwords of signed 16-bit samples into scratchpad by fromIPU DMA),
// then the EE's prediction and residual add; CSC of the frame due for display at the end. Built on
// the host from the functional decode (the macroblock trace of ipu/slice_decoder.hpp); timed by
// ipu/bdec_flow_timing.hpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ipu/slice_decoder.hpp"

namespace vbim::ipu {

// How many of each IPU command (T-IPU command codes 0-9; PACK and SETTH are not used here).
struct IpuCommandCounts {
  std::int64_t bclr = 0;
  std::int64_t idec = 0;
  std::int64_t bdec = 0;
  std::int64_t vdec = 0;
  std::int64_t fdec = 0;
  std::int64_t setiq = 0;
  std::int64_t setvq = 0;  // only for PACK to 4-bit indices: never issued by an RGB32 player
  std::int64_t csc = 0;
  IpuCommandCounts& operator+=(const IpuCommandCounts& o);
};

// One pass of libmpeg's macroblock loop (_mpeg12_slice): a coded macroblock (VDEC/FDEC, BDEC if it
// has blocks) or a skipped one (no IPU command); both are predicted by the EE.
struct FlowMacroblock {
  std::uint16_t vdec = 0;  // includes the slice's own reads when sliceStart (FDEC for its header)
  std::uint16_t fdec = 0;
  bool sliceStart = false;
  bool skipped = false;
  bool bdec = false;
  bool intra = false;            // BDEC with MBI: the EE stores the samples (no prediction)
  std::uint32_t blockBits = 0;   // what BDEC reads
  std::uint32_t needQwords = 0;  // input qwords read once this macroblock is parsed
  std::uint8_t predictions = 0;
  std::uint8_t averaged = 0;
  std::uint32_t address = 0;   // in the picture (the macroblock trace's), skipped ones included
  std::uint32_t bdecWord = 0;  // the BDEC command word, for the command log (set by IpuUnit when it records)
  // Its VDEC and FDEC words in issue order, FlowPicture::macroblockWords[wordsBegin, + wordCount),
  // for the command log (set by IpuUnit when it records; 0 words: logged from the counts, FB = 0).
  std::uint32_t wordsBegin = 0;
  std::uint32_t wordCount = 0;
};

struct FlowPicture {
  std::uint32_t inQwords = 0;                  // the picture's bytes, in qwords (toIPU)
  std::uint32_t headerQwords = 0;              // read before the first slice
  IpuCommandCounts header;                     // the headers' commands (FDEC, SETIQ, and BCLR of SetDefQM)
  std::vector<std::uint32_t> headerWords;      // the same, in the order the EE issues them (ipu/ipu_commands.hpp)
  std::vector<FlowMacroblock> macroblocks;     // in decode order
  std::vector<std::uint32_t> macroblockWords;  // the macroblocks' VDEC/FDEC words (FlowMacroblock::wordsBegin)
};

// FDEC reads of one slice header (libmpeg _mpeg12_slice: the start-code peek and skip, the
// quantiser_scale_code, extra_bit_slice).
inline constexpr int kSliceHeaderFdec = 4;

// The header commands of `bytes` before the first slice (start codes, sequence header and
// extension, GOP, picture header and extensions; SETIQ per quantiser matrix, as libmpeg reads them).
// With `words`, also their command words in issue order: per start code 2 FDECs (its peek, FB = 0,
// and its 32 bits) then the header's reads with FB = each read's width, SETIQ (IQM = 0 intra, 1
// non-intra) after the load flag of each matrix the stream loads, and for a default matrix
// _MPEG_SetDefQM's BCLR, SETIQ intra, SETIQ non-intra, BCLR. The peeks libmpeg adds when its 32-bit
// copy of IPU_TOP runs dry are not among them (the flow charges one FDEC per read).
IpuCommandCounts headerCommands(std::span<const std::uint8_t> bytes, std::uint32_t& headerBytes,
                                std::vector<std::uint32_t>* words = nullptr);

// The picture's flow. `trace` is the decoder's macroblock trace of that picture; `intraPicture`:
// an I picture, whose trace (ipu/slice_decoder.cpp) has no VDEC/FDEC counts: each macroblock then
// reads its address increment and type with VDEC, dct_type with FDEC when `fieldDct`, and BDEC
// its whole bits. Macroblocks no slice decoded (concealed) are not in the flow.
FlowPicture buildFlow(std::span<const std::uint8_t> bytes, const std::vector<MacroblockBits>& trace, bool intraPicture,
                      bool fieldDct);

}  // namespace vbim::ipu
