#include "ipu/block_walker.hpp"

#include <algorithm>
#include <cstring>

#include "ipu/bit_reader.hpp"
#include "ipu/headers.hpp"
#include "ipu/idct.hpp"
#include "ipu/idct_libmpeg2.hpp"
#include "ipu/inter_vlc.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/quant_tables.hpp"
#include "ipu/slice_syntax.hpp"
#include "ipu/start_code.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {

namespace {

// One slice walked: appends its macroblocks; false with `error` set on anything the decoder would
// report as an issue (the walker is for valid pictures).
class SliceWalker {
 public:
  SliceWalker(const WalkedPicture& pic, const PictureParams& pp, const PictureHeader& ph, const std::uint8_t* begin,
              const std::uint8_t* end, std::size_t offset)
      : pic_(pic), pp_(pp), ph_(ph), t_(vlcTables()), it_(interVlcTables()), br_(begin, end), offset_(offset) {}

  bool run(int code, std::vector<WalkedMacroblock>& out, std::string& error);

 private:
  bool fail(std::string& error, const std::string& what) const {
    error = "byte " + std::to_string(offset_ + br_.bytePosition()) + ": " + what;
    return false;
  }
  int scale(int code) const { return quantiserScale(pp_.mpeg1, pp_.qScaleType, code); }
  void resetDc() {
    const int reset = pp_.mpeg1 ? 128 : (1 << (7 + pp_.intraDcPrecision));
    dcPred_[0] = dcPred_[1] = dcPred_[2] = reset;
  }
  // An FDEC of n bits (libmpeg _MPEG_GetBits(n)) read now.
  std::uint32_t fdec(WalkedMacroblock& mb, int n) {
    mb.eeWords.push_back(fdecWord(n));
    return br_.read(n);
  }
  bool header(WalkedMacroblock& mb, int& qsc, std::string& error);
  bool motionVectors(WalkedMacroblock& mb, int s, std::string& error);
  bool vector(WalkedMacroblock& mb, int s, bool dmv, std::string& error);
  bool block(int b, int qsc, bool intra, WalkedBlock& blk, std::string& error);

  const WalkedPicture& pic_;
  const PictureParams& pp_;
  const PictureHeader& ph_;
  const VlcTables& t_;
  const InterVlcTables& it_;
  BitReader br_;
  std::size_t offset_;
  int dcPred_[3] = {0, 0, 0};
};

// f_code[s][t] as the decoder takes it: MPEG-2's picture coding extension, MPEG-1's picture header.
int fCodeOf(const WalkedPicture& pic, const PictureHeader& ph, int s, int t) {
  return pic.mpeg1 ? ph.headerFCode[s] : ph.fCode[s][t];
}

// motion_vector(r, s) (§6.2.5.3): motion_code (VDEC), motion_residual (FDEC of r_size bits when
// r_size > 0 and motion_code != 0), dmvector (VDEC), for the horizontal then the vertical part.
bool SliceWalker::vector(WalkedMacroblock& mb, int s, bool dmv, std::string& error) {
  for (int t = 0; t < 2; ++t) {
    const int f = fCodeOf(pic_, ph_, s, t);
    if (f < 1 || f > 9) return fail(error, "f_code " + std::to_string(f) + " with a motion vector");
    const VlcEntry m = t_.motionCode[br_.peek(11)];
    if (m.len == 0) return fail(error, "no motion_code");
    br_.skip(m.len);
    mb.eeWords.push_back(vdecWord(0, VdecTable::kMotionCode));
    if (m.value != 0 && f > 1) fdec(mb, f - 1);
    if (dmv) {
      mb.eeWords.push_back(vdecWord(0, VdecTable::kDmVector));
      br_.skip(br_.peek(1) ? 2 : 1);  // B.11: '0', '10', '11'
    }
  }
  return true;
}

// motion_vectors(s) (§6.2.5.2) with the field selects, for the macroblock's motion type.
bool SliceWalker::motionVectors(WalkedMacroblock& mb, int s, std::string& error) {
  if (pp_.mpeg1) return vector(mb, s, false, error);
  const bool frame = pic_.pictureStructure == 3;
  // Frame pictures: 1 field (two vectors), 2 frame, 3 dual prime; field pictures: 1 field, 2 16x8
  // (two vectors), 3 dual prime. Without motion_type (frame_pred_frame_dct, or an intra
  // macroblock's concealment vectors, §6.3.17.1): frame in a frame picture, field in a field one.
  const int type = mb.motionType != 0 ? mb.motionType : frame ? 2 : 1;
  const bool dmv = type == 3;
  const int count = (frame && type == 1) || (!frame && type == 2) ? 2 : 1;
  const bool fieldFormat = !frame || type != 2;
  if (count == 1) {
    if (fieldFormat && !dmv) fdec(mb, 1);  // motion_vertical_field_select
    return vector(mb, s, dmv, error);
  }
  for (int r = 0; r < 2; ++r) {
    fdec(mb, 1);
    if (!vector(mb, s, false, error)) return false;
  }
  return true;
}

// macroblock_type .. coded_block_pattern; the address increment is read.
bool SliceWalker::header(WalkedMacroblock& mb, int& qsc, std::string& error) {
  mb.eeWords.push_back(vdecWord(0, VdecTable::kMacroblockType));
  if (pic_.codingType == 1) {
    const VlcEntry type = t_.intraMbType[br_.peek(2)];
    if (type.len == 0) return fail(error, "not an intra macroblock_type");
    br_.skip(type.len);
    mb.type = kMbIntra | ((type.value & 1) ? kMbQuant : 0);
  } else {
    const InterVlcEntry type = (pic_.codingType == 2 ? it_.mbTypeP : it_.mbTypeB)[br_.peek(6)];
    if (type.len == 0) return fail(error, "no macroblock_type code");
    br_.skip(type.len);
    mb.type = type.value;
  }
  mb.intra = (mb.type & kMbIntra) != 0;
  const bool frame = pic_.pictureStructure == 3;
  if (!pp_.mpeg1 && (mb.type & (kMbForward | kMbBackward)) && (!frame || !ph_.framePredFrameDct)) {
    mb.motionType = static_cast<int>(fdec(mb, 2));
    if (mb.motionType == 0) return fail(error, "a reserved motion type");
  }
  if (pp_.fieldDctAllowed && (mb.type & (kMbIntra | kMbPattern))) mb.fieldDct = fdec(mb, 1) != 0;
  if (mb.type & kMbQuant) {
    qsc = static_cast<int>(fdec(mb, 5));
    if (qsc == 0) return fail(error, "quantiser_scale_code 0");
  }
  mb.quantiserScaleCode = qsc;
  if (mb.intra) {
    if (pp_.concealmentMotionVectors) {
      // motion_vectors(0) and marker_bit (§6.2.5.2): parsed, not used by the IPU.
      if (!motionVectors(mb, 0, error)) return false;
      fdec(mb, 1);
    }
    mb.codedBlockPattern = 63;
    return true;
  }
  if ((mb.type & kMbForward) && !motionVectors(mb, 0, error)) return false;
  if ((mb.type & kMbBackward) && !motionVectors(mb, 1, error)) return false;
  mb.codedBlockPattern = 0;
  return true;
}

bool SliceWalker::block(int b, int qsc, bool intra, WalkedBlock& blk, std::string& error) {
  blk.intra = intra;
  const int cc = b < 4 ? 0 : b - 3;
  int i = -1;  // the scan position of the last coefficient
  if (intra) {
    const VlcEntry e = cc == 0 ? t_.dcSizeLuma[br_.peek(9)] : t_.dcSizeChroma[br_.peek(10)];
    if (e.len == 0) return fail(error, "block " + std::to_string(b) + ": no dct_dc_size code");
    br_.skip(e.len);
    blk.dcSize = static_cast<unsigned char>(e.value);
    if (blk.dcSize != 0) {
      const int bits = static_cast<int>(br_.read(blk.dcSize));
      blk.dcDifferential = (bits >> (blk.dcSize - 1)) ? bits : bits - ((1 << blk.dcSize) - 1);
    }
    dcPred_[cc] += blk.dcDifferential;
    blk.quantised[0] = static_cast<std::int16_t>(dcPred_[cc]);
    // §7.4.1 (11172-2 §2.4.4.1: x 8): intra_dc_mult x QF[0][0].
    const int dc = pp_.mpeg1 ? dcPred_[cc] * 8 : dcPred_[cc] * (8 >> pp_.intraDcPrecision);
    blk.dequantised[0] = static_cast<std::int16_t>(std::clamp(dc, -2048, 2047));
    i = 0;
  }
  const int s = scale(qsc);
  const std::array<std::uint8_t, 64>& matrix = intra ? pic_.intraMatrix : pic_.nonIntraMatrix;
  const DctCodeEntry* shortCodes = t_.dctShort[intra && pp_.intraVlcFormat ? 1 : 0];
  for (bool first = true;; first = false) {
    RunLevel rl;
    if (!intra && first && br_.peek(1)) {
      // B.14 note 2: a non-intra block's first code '1s' is run 0, level +-1.
      br_.skip(1);
      rl.level = br_.readBit() ? -1 : 1;
    } else {
      DctCodeEntry c = shortCodes[br_.peek(VlcTables::kDctShortBits)];
      if (c.level == 0 && c.step == kDctKindLong) c = t_.dctLong[br_.peek(VlcTables::kDctLongBits)];
      if (c.level != 0) {
        br_.skip(c.bits);
        rl.run = c.step - 1;
        rl.level = c.negative ? -c.level : c.level;
      } else if (c.step == kDctKindEob && (intra || !first)) {  // a non-intra block has a coefficient
        br_.skip(c.bits);
        break;
      } else if (c.step == kDctKindEscape) {
        rl.escape = true;
        rl.level = pp_.mpeg1 ? readEscapeLevel<true>(br_, rl.run) : readEscapeLevel<false>(br_, rl.run);
      } else {
        return fail(error, "block " + std::to_string(b) + ": no DCT coefficient code");
      }
    }
    i += rl.run + 1;
    if (i > 63) return fail(error, "block " + std::to_string(b) + ": coefficients past position 63");
    blk.ac.push_back(rl);
    const int pos = pp_.scan[i];
    blk.quantised[static_cast<std::size_t>(pos)] = static_cast<std::int16_t>(rl.level);
    const int mag = rl.level < 0 ? -rl.level : rl.level;
    // 2 x level, plus sign(level) for a non-intra block (§7.4.2.3; 11172-2 §2.4.4.2).
    const int twice = 2 * mag + (intra ? 0 : 1);
    const int w = matrix[static_cast<std::size_t>(pos)];
    int v = 0;
    if (pp_.mpeg1) {
      // 11172-2 §2.4.4.1-2: (twice x quantizer_scale x W) / 16, then the magnitude made odd.
      v = twice * s * w / 16;
      if ((v & 1) == 0 && v != 0) v -= 1;
    } else {
      // 13818-2 §7.4.2.3: (twice x W x quantiser_scale) / 32, truncating toward zero.
      v = twice * w * s / 32;
    }
    // §7.4.3: saturation to [-2048, 2047].
    v = rl.level < 0 ? -std::min(v, 2048) : std::min(v, 2047);
    blk.dequantised[static_cast<std::size_t>(pos)] = static_cast<std::int16_t>(v);
  }
  if (!pp_.mpeg1) {
    // §7.4.4 mismatch control: an even sum of all coefficients toggles the LSB of F[7][7].
    int sum = 0;
    for (const std::int16_t f : blk.dequantised) sum += f;
    if ((sum & 1) == 0) blk.dequantised[63] = static_cast<std::int16_t>(blk.dequantised[63] ^ 1);
  }
  return true;
}

bool SliceWalker::run(int code, std::vector<WalkedMacroblock>& out, std::string& error) {
  const std::size_t headerStart = br_.position();
  const SliceHeader h = readSliceHeader(br_, pp_, code);
  if (!h.ok) return fail(error, "slice " + std::to_string(code) + ": bad slice header");
  // libmpeg's slice header reads: the start code's peek and its 32 bits, quantiser_scale_code,
  // then one bit (MPEG-2's intra_slice_flag or extra_bit_slice); with the flag set, 8 more bits and
  // an extra_bit_slice loop (a bit, and 8 bits after each set one).
  std::vector<std::uint32_t> sliceWords{fdecWord(0), fdecWord(32), fdecWord(5), fdecWord(1)};
  const std::size_t extraBits = br_.position() - headerStart - 5 - (pp_.tallPicture && !pp_.mpeg1 ? 3 : 0);
  if (extraBits > 1) {
    // The bit set (MPEG-2's intra_slice_flag, MPEG-1's extra_bit_slice): 8 bits (intra_slice and
    // reserved_bits, or extra_information_slice), then the extra_bit_slice loop.
    std::size_t left = extraBits - 9;
    sliceWords.push_back(fdecWord(8));
    for (; left >= 9; left -= 9) {
      sliceWords.push_back(fdecWord(1));
      sliceWords.push_back(fdecWord(8));
    }
    if (left > 0) sliceWords.push_back(fdecWord(1));
  }
  int qsc = h.quantiserScaleCode;
  resetDc();
  int address = h.row * pic_.mbWidth - 1;
  bool first = true;
  bool lastIntra = false;
  std::size_t start = headerStart;
  for (;;) {
    WalkedMacroblock mb;
    if (first) mb.eeWords = sliceWords;
    // macroblock_address_increment (B.1) as _MPEG_GetMBAI reads it: a VDEC per code, escapes and
    // MPEG-1 stuffing included.
    int inc = 0;
    for (;;) {
      const VlcEntry e = t_.mbAddressIncrement[br_.peek(11)];
      if (e.len == 0 || br_.overrun()) return fail(error, "no macroblock_address_increment code");
      br_.skip(e.len);
      mb.eeWords.push_back(vdecWord(0, VdecTable::kAddressIncrement));
      if (e.value == kMbaEscape) {
        inc += 33;
      } else if (e.value != kMbaStuffing) {
        inc += e.value;
        break;
      }
    }
    if (!first && inc > 1) {
      if (pic_.codingType == 1) return fail(error, "a skipped macroblock in an intra picture");
      mb.skippedBefore = inc - 1;
      resetDc();  // §7.2.1: a skipped macroblock resets the DC predictors
      lastIntra = false;
    }
    mb.sliceStart = first;
    address += inc;
    first = false;
    mb.address = address;
    mb.mbX = address % pic_.mbWidth;
    mb.mbY = address / pic_.mbWidth;
    if (address >= pic_.mbWidth * pic_.mbHeight || (!pp_.mpeg1 && mb.mbY != h.row)) {
      return fail(error, "macroblock address " + std::to_string(address) + " outside the slice's row");
    }
    if (!header(mb, qsc, error)) return false;
    if (!mb.intra || !lastIntra) resetDc();  // §7.2.1: after a non-intra macroblock
    lastIntra = mb.intra;
    const std::size_t blockStart = br_.position();
    if (!mb.intra && (mb.type & kMbPattern)) {
      const InterVlcEntry cbp = it_.codedBlockPattern[br_.peek(9)];
      if (cbp.len == 0) return fail(error, "no coded_block_pattern code");
      br_.skip(cbp.len);
      mb.codedBlockPattern = cbp.value;
    }
    for (int b = 0; b < 6; ++b) {
      WalkedBlock& blk = mb.blocks[static_cast<std::size_t>(b)];
      blk.coded = (mb.codedBlockPattern >> (5 - b)) & 1;
      blk.intra = mb.intra;
      if (blk.coded && !block(b, mb.quantiserScaleCode, mb.intra, blk, error)) return false;
    }
    if (br_.overrun()) return fail(error, "the slice ends inside macroblock " + std::to_string(address));
    const bool bdec = mb.intra || mb.codedBlockPattern != 0;
    mb.blockBits = bdec ? br_.position() - blockStart : 0;
    mb.bits = br_.position() - start;
    start = br_.position();
    out.push_back(std::move(mb));
    if (br_.peek(23) == 0) return true;  // the next start code (§6.2.4 nextbits())
  }
}

}  // namespace

bool walkPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index,
                 const SequenceHeader* sequence) {
  out = WalkedPicture{};
  int pictures = 0;  // picture headers seen
  SequenceHeader seq = sequence != nullptr ? *sequence : SequenceHeader{};
  PictureHeader pic;
  bool haveSequence = sequence != nullptr;
  bool pictureOpen = false;
  bool started = false;  // the first slice was seen: the picture's parameters are fixed
  PictureParams pp;
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  for (std::size_t pos = findStartCode(d, n, 0); pos + 3 < n;) {
    const int code = d[pos + 3];
    const std::size_t payload = pos + 4;
    const std::size_t next = findStartCode(d, n, payload);
    BitReader br(d + payload, d + next);
    const std::string at = "byte " + std::to_string(pos) + ": ";
    if (code >= kSliceFirst && code <= kSliceLast && pictures - 1 != index) {
      // a slice of another picture
    } else if (code >= kSliceFirst && code <= kSliceLast) {
      if (!pictureOpen) {
        error = at + "a slice before any picture header";
        return false;
      }
      if (!started) {
        started = true;
        if (!haveSequence) {
          error = at + "no sequence header before the picture";
          return false;
        }
        if (pic.codingType < 1 || pic.codingType > 3 || seq.chromaFormat != 1 ||
            (seq.mpeg2 && !pic.hasCodingExtension)) {
          error = at + "not a 4:2:0 I, P or B picture (picture_coding_type " + std::to_string(pic.codingType) +
                  ", chroma_format " + std::to_string(seq.chromaFormat) + ")";
          return false;
        }
        out.width = seq.width;
        out.height = seq.height;
        out.mbWidth = (seq.width + 15) / 16;
        out.mbHeight = (!seq.mpeg2 || seq.progressiveSequence) ? (seq.height + 15) / 16 : 2 * ((seq.height + 31) / 32);
        out.mpeg1 = !seq.mpeg2;
        out.codingType = pic.codingType;
        out.pictureStructure = seq.mpeg2 ? pic.pictureStructure : 3;
        if (out.pictureStructure != 3) out.mbHeight /= 2;  // a field's macroblock rows
        out.intraMatrix = seq.intraMatrix;
        out.nonIntraMatrix = seq.nonIntraMatrix;
        pp.mpeg1 = out.mpeg1;
        pp.mbWidth = out.mbWidth;
        pp.mbRows = out.mbHeight;
        pp.fieldPicture = out.pictureStructure != 3;
        pp.tallPicture = seq.height > 2800;
        pp.intraMatrix = seq.intraMatrix;
        pp.scan = kZigzagScan.data();
        if (seq.mpeg2) {
          out.intraDcPrecision = pp.intraDcPrecision = pic.intraDcPrecision;
          out.qScaleType = pp.qScaleType = pic.qScaleType;
          out.intraVlcFormat = pp.intraVlcFormat = pic.intraVlcFormat;
          out.alternateScan = pic.alternateScan;
          if (pic.alternateScan) pp.scan = kAlternateScan.data();
          pp.fieldDctAllowed = pic.pictureStructure == 3 && !pic.framePredFrameDct;
          pp.concealmentMotionVectors = pic.concealmentMotionVectors;
        }
      }
      SliceWalker w(out, pp, pic, d + payload, d + next, payload);
      std::string why;
      if (!w.run(code, out.macroblocks, why)) {
        error = "slice at byte " + std::to_string(pos) + ": " + why;
        return false;
      }
    } else if (started && (code == kPictureStartCode || code == kSequenceHeaderCode || code == kGroupStartCode ||
                           code == kSequenceEndCode)) {
      break;  // the picture ended
    } else if (code == kPictureStartCode) {
      pictureOpen = parsePictureHeader(br, pic);
      ++pictures;
    } else if (code == kSequenceHeaderCode) {
      haveSequence = parseSequenceHeader(br, seq);
    } else if (code == kExtensionStartCode) {
      const int id = static_cast<int>(br.read(4));
      bool ok = true;
      if (id == 1 && haveSequence) ok = parseSequenceExtension(br, seq);
      if (id == 3 && haveSequence) ok = parseQuantMatrixExtension(br, seq);
      if (id == 8 && pictureOpen) ok = parsePictureCodingExtension(br, pic);
      if (!ok) {
        error = at + "a bad extension (id " + std::to_string(id) + ")";
        return false;
      }
    }
    pos = next;
  }
  if (!started) {
    error = "no slice of picture " + std::to_string(index) + " in " + std::to_string(n) + " bytes";
    return false;
  }
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(out.mbWidth) * out.mbHeight, 0);
  for (const WalkedMacroblock& mb : out.macroblocks) {
    for (int a = mb.address - mb.skippedBefore; a <= mb.address; ++a) seen[static_cast<std::size_t>(a)] = 1;
  }
  const auto missing = std::find(seen.begin(), seen.end(), std::uint8_t{0});
  if (missing != seen.end()) {
    const int a = static_cast<int>(missing - seen.begin());
    error = "macroblock " + std::to_string(a) + " (column " + std::to_string(a % out.mbWidth) + ", row " +
            std::to_string(a / out.mbWidth) + ") is in no slice";
    return false;
  }
  return true;
}

bool walkIntraPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index) {
  if (!walkPicture(bytes, out, error, index)) return false;
  if (out.codingType != 1 || out.pictureStructure != 3) {
    error = "picture " + std::to_string(index) + ": not a 4:2:0 intra frame picture (picture_coding_type " +
            std::to_string(out.codingType) + ", picture_structure " + std::to_string(out.pictureStructure) + ")";
    return false;
  }
  return true;
}

void idctResult(IdctKind kind, const std::int16_t* coeffs, std::int16_t* out) {
  switch (kind) {
    case IdctKind::Pcsx2:
      idctPcsx2(coeffs, out);
      return;
    case IdctKind::Libmpeg2:
      idctLibmpeg2(coeffs, out);
      return;
    case IdctKind::Exact:
      idctSignedUnclipped(coeffs, 0xFF, out);
      return;
  }
}

void idctSamples(IdctKind kind, const std::int16_t* coeffs, std::uint8_t* out) {
  std::int16_t r[64];
  idctResult(kind, coeffs, r);
  for (int i = 0; i < 64; ++i) out[i] = static_cast<std::uint8_t>(std::clamp<int>(r[i], 0, 255));
}

void nonIntraResidual(IdctKind kind, const WalkedBlock& block, std::int16_t* out) {
  const int dc = block.dequantised[0];
  if (kind != IdctKind::Exact && block.firstOnly() && nonIntraDcShortcut(dc)) {
    for (int i = 0; i < 64; ++i) out[i] = static_cast<std::int16_t>(nonIntraDcResidual(dc));
    return;
  }
  idctResult(kind, block.dequantised.data(), out);
}

FrameStore assembleIntraPicture(const WalkedPicture& picture, IdctKind kind) {
  FrameStore fs;
  fs.reset(picture.mbWidth, picture.mbHeight);
  for (const WalkedMacroblock& mb : picture.macroblocks) {
    for (int b = 0; b < 6; ++b) {
      std::uint8_t px[64];
      idctSamples(kind, mb.blocks[static_cast<std::size_t>(b)].dequantised.data(), px);
      std::uint8_t* dst = nullptr;
      std::ptrdiff_t stride = 0;
      if (b < 4) {
        // Blocks 0/1 on top, 2/3 below; with field DCT (§6.1.3) 0/1 hold the top field's lines.
        const std::ptrdiff_t ls = fs.lumaStride;
        stride = mb.fieldDct ? 2 * ls : ls;
        const std::ptrdiff_t x = std::ptrdiff_t{16} * mb.mbX + std::ptrdiff_t{8} * (b & 1);
        dst = fs.y.data() + ls * 16 * mb.mbY + x + (mb.fieldDct ? ls : 8 * ls) * (b >> 1);
      } else {
        stride = fs.chromaStride;
        dst = (b == 4 ? fs.cb.data() : fs.cr.data()) + stride * 8 * mb.mbY + std::ptrdiff_t{8} * mb.mbX;
      }
      for (std::ptrdiff_t r = 0; r < 8; ++r) std::memcpy(dst + stride * r, px + 8 * r, 8);
    }
  }
  return fs;
}

}  // namespace vbim::ipu
