// A slow, plain walk of a picture's blocks for the per-stage known-answer vectors (docs/porting.md,
// "Per-stage vectors"): every block's DC size and differential and AC run/level pairs as the
// bitstream codes them, its 64 quantised coefficients QF, and its 64 dequantised coefficients F
// (saturated, mismatch control applied) as IDEC or BDEC hands them to the IDCT; and per macroblock
// its modes and the reads the EE makes of its header in the BDEC flow (libmpeg's VDEC and FDEC
// words, for the command log of `vbim play --trace-detail ipu`). It reads the slices with the
// decoder's own VLC tables and slice-syntax pieces (ipu/vlc_tables.hpp, ipu/inter_vlc.hpp,
// ipu/slice_syntax.hpp) but keeps every intermediate value, which the hot slice decoders fold away.
// I, P and B pictures, frame or field. Checked against the decoder (tests/ipu/block_walker_test.cpp):
// for an intra frame picture, assembleIntraPicture() of its blocks is the decoder's picture bit for
// bit; for every picture, each macroblock's address, bits, BDEC bits and VDEC/FDEC counts are the
// decoder's macroblock trace (ipu/slice_decoder.hpp MacroblockBits).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ipu/frame_store.hpp"
#include "ipu/headers.hpp"
#include "ipu/kernels.hpp"

namespace vbim::ipu {

struct RunLevel {
  int run = 0;
  int level = 0;  // signed
  bool escape = false;
};

struct WalkedBlock {
  bool coded = true;         // in coded_block_pattern (every block of an intra macroblock)
  bool intra = true;         // intra: DC then AC; non-intra: every coefficient in `ac`, from position 0
  int dcSize = 0;            // dct_dc_size_luminance / _chrominance (intra)
  int dcDifferential = 0;    // dct_dc_differential as a signed value (0 when dcSize is 0)
  std::vector<RunLevel> ac;  // in bitstream order, up to end of block; a non-intra block's first run counts from 0
  // Natural (raster) order, F[v][u] at 8v + u. quantised[0] is the predicted DC (the predictor plus
  // the differential); the others are the signed levels placed by the scan.
  std::array<std::int16_t, 64> quantised{};
  // §7.4: the inverse quantisation, saturation to [-2048, 2047] and (MPEG-2) mismatch control.
  std::array<std::int16_t, 64> dequantised{};
  // A non-intra block whose only coded coefficient is the first in scan order (the decoders' DC
  // shortcut, ipu/idct_libmpeg2.hpp).
  bool firstOnly() const { return !intra && ac.size() == 1 && ac[0].run == 0; }
};

// macroblock_type flags as ipu/inter_vlc.hpp's kMb* (quant 1, forward 2, backward 4, pattern 8, intra 16).

struct WalkedMacroblock {
  int address = 0;  // mbY * mbWidth + mbX (a field picture: rows of the field)
  int mbX = 0;
  int mbY = 0;
  int skippedBefore = 0;  // skipped macroblocks just before it in its slice (P and B pictures)
  bool sliceStart = false;
  int type = 16;  // macroblock_type flags (intra: 16, with quant 17)
  bool intra = true;
  int motionType = 0;          // frame_motion_type / field_motion_type when the stream codes it, else 0
  int quantiserScaleCode = 0;  // the one its blocks use (its own with the quant flag, else the slice's)
  bool fieldDct = false;       // dct_type
  int codedBlockPattern = 63;  // bit 5 block 0 .. bit 0 block 5
  std::size_t bits = 0;        // bits of the macroblock (the first of a slice includes the slice header)
  std::size_t blockBits = 0;   // what BDEC reads: coded_block_pattern and blocks (intra: the blocks)
  // The EE's reads of its header in the BDEC flow, as libmpeg issues them (ee/mpeg/src/libmpeg.c
  // _mpeg12_slice, _mpeg12_dec_mb; libmpeg_core.c): IPU command words (ipu/ipu_commands.hpp). A
  // slice's first macroblock starts with the slice header's FDECs (the start code's peek and its
  // 32 bits, quantiser_scale_code, extra_bit_slice); then VDEC of each address increment code and
  // of macroblock_type, an FDEC per fixed-length field with FB = its width (motion type, dct_type,
  // quantiser_scale_code, field selects, motion residuals, the concealment marker) and VDEC per
  // motion code and dmvector, in bitstream order. FDEC FB = n is _ipu_get_bits(n): it skips the n
  // bits the EE has read from IPU_TOP. The peeks (FDEC 0) libmpeg adds when its 32-bit copy of
  // IPU_TOP runs dry are not among them: inside a macroblock header it does not (a VDEC refills it).
  std::vector<std::uint32_t> eeWords;
  std::array<WalkedBlock, 6> blocks;  // Y0 Y1 Y2 Y3 Cb Cr
};

struct WalkedPicture {
  int width = 0;
  int height = 0;
  int mbWidth = 0;
  int mbHeight = 0;
  bool mpeg1 = false;
  int codingType = 1;        // 1 I, 2 P, 3 B
  int pictureStructure = 3;  // 1 top field, 2 bottom field, 3 frame
  int intraDcPrecision = 0;
  bool qScaleType = false;
  bool intraVlcFormat = false;
  bool alternateScan = false;
  std::array<std::uint8_t, 64> intraMatrix{};     // raster order
  std::array<std::uint8_t, 64> nonIntraMatrix{};  // raster order
  std::vector<WalkedMacroblock> macroblocks;      // coded macroblocks, in bitstream order
};

// Walks picture `index` (0 the first; a field is a picture) of `bytes`, with the headers before it
// (a picture as the EE hands it to the IPU, or an elementary stream): a 4:2:0 I, P or B picture,
// frame or field. False with `error` naming the byte offset and what was found for anything else (a
// D picture, another chroma format, a corrupt code, a missing slice). `sequence`: the sequence
// header (with its extensions and matrices) in force when `bytes` hold none, as for every picture
// but a GOP's first that a player hands the IPU.
bool walkPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index = 0,
                 const SequenceHeader* sequence = nullptr);
// The same for an intra frame picture only (what IDEC decodes); a P, B or field picture is refused
// with its picture_coding_type and picture_structure, as is a skipped macroblock.
bool walkIntraPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index = 0);

// The IDCT's 64 results for dequantised coefficients, before any clip: Pcsx2 and Libmpeg2 as
// ipu/idct_libmpeg2.hpp computes them, Exact as idctSignedUnclipped (ipu/idct.hpp).
void idctResult(IdctKind kind, const std::int16_t* coeffs, std::int16_t* out);
// An intra block's samples as IDEC writes them: idctResult clamped to 0..255.
void idctSamples(IdctKind kind, const std::int16_t* coeffs, std::uint8_t* out);
// A non-intra block's residual, which the decoder adds to the prediction: idctResult, or for a
// firstOnly() block with Pcsx2 or Libmpeg2 the decoders' shortcut, (F[0][0] + 4) >> 3 everywhere,
// where it applies (nonIntraDcShortcut), as the decoder's add kernels do (ipu/kernels.cpp).
void nonIntraResidual(IdctKind kind, const WalkedBlock& block, std::int16_t* out);

// Every block's idctSamples placed where the picture's macroblock puts it (field DCT included).
FrameStore assembleIntraPicture(const WalkedPicture& picture, IdctKind kind);

}  // namespace vbim::ipu
