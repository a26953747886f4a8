#include "ipu/slice_decoder.hpp"

#include <cstddef>
#include <cstring>

#include "ipu/bit_reader.hpp"
#include "ipu/clear_block.hpp"
#include "ipu/idct.hpp"
#include "ipu/quant_tables.hpp"
#include "ipu/slice_syntax.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {
namespace {

// One macroblock's coefficients before reconstruction: 4 luma and 2 chroma blocks.
struct alignas(32) MacroblockCoefficients {
  std::int16_t block[6][64];
  unsigned rowMask[6];
  unsigned colMask[6];
  bool acPresent[6];
};

class SliceDecoder {
 public:
  SliceDecoder(const PictureParams& pp, const std::uint8_t* begin, const std::uint8_t* end, std::size_t offset,
               const SliceOutput& out)
      : pp_(pp), t_(vlcTables()), br_(begin, end), offset_(offset), out_(out) {
    std::memset(&mb_, 0, sizeof(mb_));
  }

  void run(int code);

 private:
  enum class Status { kOk, kError };

  void issue(IssueKind kind, int mbX, int mbY) { out_.report->add(kind, offset_ + br_.bytePosition(), mbX, mbY); }
  void setQuantiserScale(int code);
  void resetDcPredictors() {
    const int reset = pp_.mpeg1 ? 128 : (1 << (7 + pp_.intraDcPrecision));
    dcPred_[0] = dcPred_[1] = dcPred_[2] = reset;
  }
  bool skipConcealmentVectors();
  template <bool Mpeg1>
  Status parseBlocks(IssueKind& why);
  template <bool Mpeg1>
  Status parseBlock(BitReader& br, int b, IssueKind& why);
  void reconstruct(int mbX, int mbY, bool fieldDct);
  void storeBlock(int b, std::uint8_t* dst, int stride);

  const PictureParams& pp_;
  const VlcTables& t_;
  BitReader br_;
  std::size_t offset_;
  const SliceOutput& out_;
  int dcPred_[3] = {128, 128, 128};
  // Per scan position: intra matrix x quantiser_scale at it, its row bit (bits 0-7) and column bit
  // (bits 8-15), and its raster index; one lookup once the run is known.
  struct ScanSlot {
    std::int32_t wq;
    std::uint16_t mask;
    std::uint8_t pos;
  };
  ScanSlot scan_[64];
  MacroblockCoefficients mb_;
};

void SliceDecoder::setQuantiserScale(int code) {
  const int scale = quantiserScale(pp_.mpeg1, pp_.qScaleType, code);
  for (int i = 0; i < 64; ++i) {
    const int pos = pp_.scan[i];
    scan_[i].pos = static_cast<std::uint8_t>(pos);
    scan_[i].wq = pp_.intraMatrix[pos] * scale;
    scan_[i].mask = static_cast<std::uint16_t>((1u << (pos >> 3)) | (1u << (8 + (pos & 7))));
  }
}

// motion_vectors(0) + marker_bit of an intra macroblock with concealment_motion_vectors (§6.2.5.2).
// The IPU does no motion compensation; the vectors are parsed and dropped.
bool SliceDecoder::skipConcealmentVectors() {
  if (pp_.fieldPicture) br_.skip(1);  // motion_vertical_field_select[0][0]
  for (int t = 0; t < 2; ++t) {
    const VlcEntry e = t_.motionCode[br_.peek(11)];
    if (e.len == 0) return false;
    br_.skip(e.len);
    const int rSize = pp_.fCode[t] - 1;
    if (e.value != 0 && rSize > 0) br_.skip(rSize);  // motion_residual
  }
  br_.skip(1);  // marker_bit
  return !br_.overrun();
}

template <bool Mpeg1>
SliceDecoder::Status SliceDecoder::parseBlocks(IssueKind& why) {
  // The reader lives in registers for the six blocks (a member would be stored and reloaded after
  // every coefficient, which puts a store-to-load round trip on the serial chain of codes).
  BitReader br = br_;
  Status status = Status::kOk;
  for (int b = 0; b < 6 && status == Status::kOk; ++b) status = parseBlock<Mpeg1>(br, b, why);
  br_ = br;
  return status;
}

template <bool Mpeg1>
[[gnu::always_inline]] inline SliceDecoder::Status SliceDecoder::parseBlock(BitReader& br, int b, IssueKind& why) {
  std::int16_t* blk = mb_.block[b];
  const int cc = b < 4 ? 0 : b - 3;
  // DC coefficient (§7.2.1): size VLC, differential, prediction.
  VlcEntry e = cc == 0 ? t_.dcSizeLuma[br.peek(9)] : t_.dcSizeChroma[br.peek(10)];
  if (e.len == 0) {
    why = IssueKind::kBadVlc;
    return Status::kError;
  }
  br.skip(e.len);
  const int size = static_cast<unsigned char>(e.value);  // 0..11 (a DC size)
  if (size != 0) {
    const int bits = static_cast<int>(br.read(size));
    // §7.2.1: a differential below half its range is negative, bits - (2^size - 1); the offset by a
    // mask, as a branch on the sign was a coin toss.
    dcPred_[cc] += bits - (((1 << size) - 1) & (((bits >> (size - 1)) & 1) - 1));
  }
  int dc = Mpeg1 ? dcPred_[cc] * 8 : dcPred_[cc] << (3 - pp_.intraDcPrecision);
  dc = dc < -2048 ? -2048 : (dc > 2047 ? 2047 : dc);
  blk[0] = static_cast<std::int16_t>(dc);
  unsigned parity = static_cast<unsigned>(dc);
  unsigned masks = 0;

  // AC coefficients (§7.2.2, §7.3, §7.4.2-7.4.3).
  const int format = pp_.intraVlcFormat ? 1 : 0;
  const DctPairEntry* pairs = t_.dctPairs[format];
  const DctCodeEntry* shortCodes = t_.dctShort[format];
  const DctCodeEntry* longCodes = t_.dctLong;
  // Past the slice's bytes the reader yields zeros, which are no code of either table, so the loop
  // ends within 16 bits; the caller checks for overrun once per macroblock.
  int i = 0;
  // The value of the coefficient of magnitude mag at a scan slot (mag 0: zero).
  auto value = [&](const ScanSlot& slot, int mag, int negative) {
    int v;
    if (Mpeg1) {
      // 11172-2 §2.4.4.1: (2 * level * quantizer_scale * W) / 16, then towards an odd value.
      v = (mag * slot.wq) >> 3;
      if ((v & 1) == 0 && v != 0) v -= 1;
    } else {
      // 13818-2 §7.4.2.3: (2 * QF * W * quantiser_scale) / 32, truncating towards zero.
      v = (mag * slot.wq) >> 4;
    }
    // §7.4.3 saturation to [-2048, 2047], applied to the magnitude before the sign.
    const int signMask = -negative;
    const int limit = 2047 - signMask;
    v = v > limit ? limit : v;
    return (v ^ signMask) - signMask;
  };
  // Places the coefficient of magnitude mag at scan position i; false if i is past the block.
  auto place = [&](int mag, int negative) {
    if (i > 63) [[unlikely]]
      return false;
    const ScanSlot& slot = scan_[i];
    const int v = value(slot, mag, negative);
    blk[slot.pos] = static_cast<std::int16_t>(v);
    parity ^= static_cast<unsigned>(v);
    masks |= slot.mask;
    return true;
  };
  for (;;) {
    br.topUp();  // at least 56 bits
    // Up to four lookups of one or two short codes (at most kDctPairBits bits each, with the EOB after them)
    // need no look at the bit count.
    int k = 0;
    bool ended = false;
    for (; k < 4; ++k) {
      const DctPairEntry p = pairs[br.peek(VlcTables::kDctPairBits)];
      if (p.step1 == 0) [[unlikely]]
        break;
      const int i1 = i + p.step1;
      const int i2 = i1 + p.step2;  // i1 when there is no second code
      if (i2 > 63) [[unlikely]] {
        // Past the block: consume what the code-at-a-time reading had when it found that (the
        // first code, or both), so the reported place is the same.
        constexpr std::uint32_t kShortMask = (1u << VlcTables::kDctShortBits) - 1;
        const int first = shortCodes[br.peek(VlcTables::kDctShortBits)].bits;
        const int second = shortCodes[br.peek(first + VlcTables::kDctShortBits) & kShortMask].bits;
        br.skipUnchecked(i1 > 63 ? first : first + second);
        why = IssueKind::kCoefficientOverrun;
        return Status::kError;
      }
      br.skipUnchecked(p.bits);
      // The second first: without one it is a zero at the first's slot, which the first then
      // overwrites (no branch on how many codes the entry holds).
      const ScanSlot& slot2 = scan_[i2];
      const ScanSlot& slot1 = scan_[i1];
      const int v2 = value(slot2, p.level2, p.negative2);
      const int v1 = value(slot1, p.level1, p.negative1);
      blk[slot2.pos] = static_cast<std::int16_t>(v2);
      blk[slot1.pos] = static_cast<std::int16_t>(v1);
      parity ^= static_cast<unsigned>(v1 ^ v2);
      masks |= slot1.mask | slot2.mask;
      i = i2;
      if (p.eob) {
        ended = true;
        break;
      }
    }
    if (ended) break;
    if (k == 4) continue;
    // Any other symbol; at least 56 - 3 * 11 = 23 bits are left.
    DctCodeEntry s = shortCodes[br.peek(VlcTables::kDctShortBits)];
    if (s.step == kDctKindLong) {
      // 12..16 bits and the sign: seven zeros, so the next 17 bits are the index.
      s = longCodes[br.peek(VlcTables::kDctLongBits)];
      if (s.level == 0) {
        why = IssueKind::kBadVlc;
        return Status::kError;
      }
      br.skipUnchecked(s.bits);
      i += s.step;
      if (!place(s.level, s.negative)) {
        why = IssueKind::kCoefficientOverrun;
        return Status::kError;
      }
    } else if (s.step == kDctKindEob) {
      br.skipUnchecked(s.bits);
      break;
    } else if (s.step == kDctKindEscape) {
      // Escape: 6-bit run, then a 12-bit signed level (MPEG-1: 8 or 16 bits, 11172-2 §2.4.3.7).
      // skip() and read() refill as they go.
      int run = 0;
      const int level = readEscapeLevel<Mpeg1>(br, run);
      const int negative = level < 0;
      i += run + 1;
      if (!place(negative ? -level : level, negative)) {
        why = IssueKind::kCoefficientOverrun;
        return Status::kError;
      }
    } else {
      why = IssueKind::kBadVlc;
      return Status::kError;
    }
  }
  // The callers' reads refill when the count is low; restore that invariant.
  if (br.bitsCached() < 32) br.topUp();
  unsigned rowMask = 1u | (masks & 0xFF);
  unsigned colMask = 1u | (masks >> 8);
  const bool ac = masks != 0;
  // §7.4.4 mismatch control: if the sum of all coefficients is even, toggle the LSB of F[7][7].
  // By masks, not a branch: an intra block's parity is a coin toss. F[7][7] = +-1 alone in its row
  // and column is kIdctToggleOnly; with a coefficient in row 7 or column 7 both bits 7 are set.
  if constexpr (!Mpeg1) {
    const unsigned even = ~parity & 1u;
    blk[63] = static_cast<std::int16_t>(blk[63] ^ static_cast<int>(even));
    const unsigned edge = ((rowMask | colMask) >> 7) & 1u;
    rowMask |= (even & (edge ^ 1u)) * kIdctToggleOnly | (even & edge) << 7;
    colMask |= (even & edge) << 7;
  }
  mb_.rowMask[b] = rowMask;
  mb_.colMask[b] = colMask;
  mb_.acPresent[b] = ac;
  return Status::kOk;
}

void SliceDecoder::storeBlock(int b, std::uint8_t* dst, int stride) {
  std::int16_t* blk = mb_.block[b];
  const unsigned rowMask = mb_.rowMask[b];
  const int dc = blk[0];
  // DC only, or DC that is a multiple of 8 plus only the mismatch toggle of F[7][7]: the exact
  // transform is the constant dc / 8 (the toggle adds less than 0.25 everywhere), and every
  // IdctKind gives the same value (checked exhaustively in tests/ipu/idct_test.cpp).
  const bool dcOnly = !mb_.acPresent[b] && (rowMask == 1 || (dc & 7) == 0);
  if (dcOnly) {
    const std::uint8_t v = idctDcValue(dc);
    for (int yy = 0; yy < 8; ++yy) std::memset(dst + static_cast<std::ptrdiff_t>(yy) * stride, v, 8);
  } else {
    pp_.idct(blk, rowMask, mb_.colMask[b], dst, stride);
  }
  clearBlock(blk);
}

void SliceDecoder::reconstruct(int mbX, int mbY, bool fieldDct) {
  const std::ptrdiff_t stride = pp_.yStride;
  std::uint8_t* y = pp_.y + stride * 16 * mbY + std::ptrdiff_t{16} * mbX;
  // Block b is the left or right half (b & 1) and the top or bottom (b >> 1). §6.1.3 field DCT:
  // blocks 0/1 hold the top field lines, 2/3 the bottom field lines.
  const std::ptrdiff_t down = fieldDct ? stride : 8 * stride;
  const int blockStride = fieldDct ? 2 * pp_.yStride : pp_.yStride;
  for (int b = 0; b < 4; ++b) storeBlock(b, y + std::ptrdiff_t{8} * (b & 1) + down * (b >> 1), blockStride);
  const std::size_t c = static_cast<std::size_t>(mbY) * 8 * pp_.cStride + static_cast<std::size_t>(mbX) * 8;
  storeBlock(4, pp_.cb + c, pp_.cStride);
  storeBlock(5, pp_.cr + c, pp_.cStride);
}

void SliceDecoder::run(int code) {
  const SliceHeader h = readSliceHeader(br_, pp_, code);
  const int row = h.row;
  if (!h.ok) {
    issue(h.why, -1, row);
    return;
  }
  int qsc = h.quantiserScaleCode;
  setQuantiserScale(qsc);
  resetDcPredictors();

  const int total = pp_.mbWidth * pp_.mbRows;
  int address = row * pp_.mbWidth - 1;
  bool firstMb = true;
  std::size_t mbStart = 0;  // bit position where the current macroblock's bits began (slice start for the first)
  for (;;) {
    int inc = 0;
    const int curX = address < 0 ? 0 : (address + 1) % pp_.mbWidth;
    const int curY = address < 0 ? row : (address + 1) / pp_.mbWidth;
    if (!readAddressIncrement(br_, t_, inc)) {
      issue(br_.overrun() ? IssueKind::kTruncatedSlice : IssueKind::kBadVlc, curX, curY);
      return;
    }
    if (!firstMb && inc > 1) {
      // Skipped macroblocks are not allowed in intra pictures: they keep their previous value.
      issue(IssueKind::kBadMacroblockAddress, curX, curY);
      resetDcPredictors();
    }
    address += inc;
    firstMb = false;
    const int mbX = address % pp_.mbWidth;
    const int mbY = address / pp_.mbWidth;
    // MPEG-2 slices stay on their row (§6.1.2); MPEG-1 slices may run on until the picture ends.
    if (address >= total || (!pp_.mpeg1 && mbY != row)) {
      issue(IssueKind::kBadMacroblockAddress, mbX, mbY);
      return;
    }
    const VlcEntry type = t_.intraMbType[br_.peek(2)];
    if (type.len == 0) {
      issue(IssueKind::kBadVlc, mbX, mbY);  // a P/B macroblock type or garbage
      return;
    }
    br_.skip(type.len);
    bool fieldDct = false;
    if (pp_.fieldDctAllowed) fieldDct = br_.readBit();
    if (fieldDct) ++out_.report->fieldDctMacroblocks;
    if (type.value & 1) {
      qsc = static_cast<int>(br_.read(5));
      if (qsc == 0) {
        issue(IssueKind::kBadHeader, mbX, mbY);
        return;
      }
      setQuantiserScale(qsc);
    }
    if (pp_.concealmentMotionVectors && !skipConcealmentVectors()) {
      issue(br_.overrun() ? IssueKind::kTruncatedSlice : IssueKind::kBadVlc, mbX, mbY);
      return;
    }
    IssueKind why = IssueKind::kBadVlc;
    if ((pp_.mpeg1 ? parseBlocks<true>(why) : parseBlocks<false>(why)) == Status::kError) {
      if (br_.overrun()) why = IssueKind::kTruncatedSlice;
      issue(why, mbX, mbY);
      // Coefficients already parsed are dropped; the macroblock keeps its previous value.
      std::memset(&mb_, 0, sizeof(mb_));
      return;
    }
    if (br_.overrun()) {
      issue(IssueKind::kTruncatedSlice, mbX, mbY);
      return;
    }
    reconstruct(mbX, mbY, fieldDct);
    (*out_.decoded)[static_cast<std::size_t>(mbY) * static_cast<std::size_t>(out_.decodedStride) +
                    static_cast<std::size_t>(mbX)] = 1;
    recordMacroblock(out_.trace, address, br_.position(), mbStart, offset_);
    // The slice ends where the next start code begins: 23 zero bits (§6.2.4 nextbits()). Past the
    // slice's bytes the reader supplies zeros, so this also ends a slice cut short.
    if (br_.peek(23) == 0) return;
  }
}

}  // namespace

void decodeSlice(const PictureParams& pp, int code, const std::uint8_t* begin, const std::uint8_t* end,
                 std::size_t offset, const SliceOutput& out) {
  SliceDecoder d(pp, begin, end, offset, out);
  d.run(code);
}

}  // namespace vbim::ipu
