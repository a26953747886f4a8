#include "ipu/block_walker.hpp"

#include <algorithm>
#include <cstring>

#include "ipu/bit_reader.hpp"
#include "ipu/headers.hpp"
#include "ipu/idct.hpp"
#include "ipu/idct_libmpeg2.hpp"
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
      : pic_(pic), pp_(pp), ph_(ph), t_(vlcTables()), br_(begin, end), offset_(offset) {}

  bool run(int code, std::vector<WalkedMacroblock>& out, std::string& error);

 private:
  bool fail(std::string& error, const std::string& what) const {
    error = "byte " + std::to_string(offset_ + br_.bytePosition()) + ": " + what;
    return false;
  }
  int scale(int code) const { return quantiserScale(pp_.mpeg1, pp_.qScaleType, code); }
  bool block(int b, int qsc, WalkedBlock& blk, std::string& error);

  const WalkedPicture& pic_;
  const PictureParams& pp_;
  const PictureHeader& ph_;
  const VlcTables& t_;
  BitReader br_;
  std::size_t offset_;
  int dcPred_[3] = {0, 0, 0};
};

bool SliceWalker::block(int b, int qsc, WalkedBlock& blk, std::string& error) {
  const int cc = b < 4 ? 0 : b - 3;
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

  const int s = scale(qsc);
  const DctCodeEntry* shortCodes = t_.dctShort[pp_.intraVlcFormat ? 1 : 0];
  int i = 0;
  for (;;) {
    DctCodeEntry c = shortCodes[br_.peek(VlcTables::kDctShortBits)];
    RunLevel rl;
    if (c.level == 0 && c.step == kDctKindLong) c = t_.dctLong[br_.peek(VlcTables::kDctLongBits)];
    if (c.level != 0) {
      br_.skip(c.bits);
      rl.run = c.step - 1;
      rl.level = c.negative ? -c.level : c.level;
    } else if (c.step == kDctKindEob) {
      br_.skip(c.bits);
      break;
    } else if (c.step == kDctKindEscape) {
      rl.escape = true;
      rl.level = pp_.mpeg1 ? readEscapeLevel<true>(br_, rl.run) : readEscapeLevel<false>(br_, rl.run);
    } else {
      return fail(error, "block " + std::to_string(b) + ": no DCT coefficient code");
    }
    i += rl.run + 1;
    if (i > 63) return fail(error, "block " + std::to_string(b) + ": coefficients past position 63");
    blk.ac.push_back(rl);
    const int pos = pp_.scan[i];
    blk.quantised[static_cast<std::size_t>(pos)] = static_cast<std::int16_t>(rl.level);
    const int mag = rl.level < 0 ? -rl.level : rl.level;
    int v = 0;
    if (pp_.mpeg1) {
      // 11172-2 §2.4.4.1: (2 x level x quantizer_scale x W) / 16, then the magnitude made odd.
      v = mag * s * pp_.intraMatrix[static_cast<std::size_t>(pos)] / 8;
      if ((v & 1) == 0 && v != 0) v -= 1;
    } else {
      // 13818-2 §7.4.2.3: (2 x QF x W x quantiser_scale) / 32, truncating toward zero.
      v = 2 * mag * s * pp_.intraMatrix[static_cast<std::size_t>(pos)] / 32;
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
  const SliceHeader h = readSliceHeader(br_, pp_, code);
  if (!h.ok) return fail(error, "slice " + std::to_string(code) + ": bad slice header");
  int qsc = h.quantiserScaleCode;
  const int reset = pp_.mpeg1 ? 128 : (1 << (7 + pp_.intraDcPrecision));
  dcPred_[0] = dcPred_[1] = dcPred_[2] = reset;
  int address = h.row * pic_.mbWidth - 1;
  bool first = true;
  std::size_t start = 0;
  for (;;) {
    int inc = 0;
    if (!readAddressIncrement(br_, t_, inc)) return fail(error, "no macroblock_address_increment code");
    if (!first && inc > 1) return fail(error, "a skipped macroblock in an intra picture");
    address += inc;
    first = false;
    WalkedMacroblock mb;
    mb.address = address;
    mb.mbX = address % pic_.mbWidth;
    mb.mbY = address / pic_.mbWidth;
    if (address >= pic_.mbWidth * pic_.mbHeight || (!pp_.mpeg1 && mb.mbY != h.row)) {
      return fail(error, "macroblock address " + std::to_string(address) + " outside the slice's row");
    }
    const VlcEntry type = t_.intraMbType[br_.peek(2)];
    if (type.len == 0) return fail(error, "not an intra macroblock_type");
    br_.skip(type.len);
    if (pp_.fieldDctAllowed) mb.fieldDct = br_.readBit();
    if (type.value & 1) {
      qsc = static_cast<int>(br_.read(5));
      if (qsc == 0) return fail(error, "quantiser_scale_code 0");
    }
    mb.quantiserScaleCode = qsc;
    if (pp_.concealmentMotionVectors) {
      // motion_vectors(0) and marker_bit (§6.2.5.2): parsed, not used by the IPU.
      for (int t = 0; t < 2; ++t) {
        const VlcEntry m = t_.motionCode[br_.peek(11)];
        if (m.len == 0) return fail(error, "no motion_code");
        br_.skip(m.len);
        if (m.value != 0 && ph_.fCode[0][t] > 1) br_.skip(ph_.fCode[0][t] - 1);
      }
      br_.skip(1);
    }
    for (int b = 0; b < 6; ++b) {
      if (!block(b, qsc, mb.blocks[static_cast<std::size_t>(b)], error)) return false;
    }
    if (br_.overrun()) return fail(error, "the slice ends inside macroblock " + std::to_string(address));
    mb.bits = br_.position() - start;
    start = br_.position();
    out.push_back(std::move(mb));
    if (br_.peek(23) == 0) return true;  // the next start code (§6.2.4 nextbits())
  }
}

}  // namespace

bool walkIntraPicture(std::span<const std::uint8_t> bytes, WalkedPicture& out, std::string& error, int index) {
  out = WalkedPicture{};
  int pictures = 0;  // picture headers seen
  SequenceHeader seq;
  PictureHeader pic;
  bool haveSequence = false;
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
        if (pic.codingType != 1 || (seq.mpeg2 && pic.pictureStructure != 3) || seq.chromaFormat != 1 ||
            (seq.mpeg2 && !pic.hasCodingExtension)) {
          error = at + "not a 4:2:0 intra frame picture (picture_coding_type " + std::to_string(pic.codingType) +
                  ", picture_structure " + std::to_string(pic.pictureStructure) + ")";
          return false;
        }
        out.width = seq.width;
        out.height = seq.height;
        out.mbWidth = (seq.width + 15) / 16;
        out.mbHeight = (!seq.mpeg2 || seq.progressiveSequence) ? (seq.height + 15) / 16 : 2 * ((seq.height + 31) / 32);
        out.mpeg1 = !seq.mpeg2;
        out.intraMatrix = seq.intraMatrix;
        pp.mpeg1 = out.mpeg1;
        pp.mbWidth = out.mbWidth;
        pp.mbRows = out.mbHeight;
        pp.tallPicture = seq.height > 2800;
        pp.intraMatrix = seq.intraMatrix;
        pp.scan = kZigzagScan.data();
        if (seq.mpeg2) {
          out.intraDcPrecision = pp.intraDcPrecision = pic.intraDcPrecision;
          out.qScaleType = pp.qScaleType = pic.qScaleType;
          out.intraVlcFormat = pp.intraVlcFormat = pic.intraVlcFormat;
          out.alternateScan = pic.alternateScan;
          if (pic.alternateScan) pp.scan = kAlternateScan.data();
          pp.fieldDctAllowed = !pic.framePredFrameDct;
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
  for (const WalkedMacroblock& mb : out.macroblocks) seen[static_cast<std::size_t>(mb.address)] = 1;
  const auto missing = std::find(seen.begin(), seen.end(), std::uint8_t{0});
  if (missing != seen.end()) {
    const int a = static_cast<int>(missing - seen.begin());
    error = "macroblock " + std::to_string(a) + " (column " + std::to_string(a % out.mbWidth) + ", row " +
            std::to_string(a / out.mbWidth) + ") is in no slice";
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
