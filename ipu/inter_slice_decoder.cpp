#include "ipu/inter_slice_decoder.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "ipu/bit_reader.hpp"
#include "ipu/inter_vlc.hpp"
#include "ipu/motion_vectors.hpp"
#include "ipu/quant_tables.hpp"
#include "ipu/slice_syntax.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {
namespace {

// frame_motion_type / field_motion_type values (Tables 6-17, 6-18).
constexpr int kMotionField = 1;  // field-based
constexpr int kMotionFrame = 2;  // frame-based (frame pictures); 16x8 (field pictures)
constexpr int kMotion16x8 = 2;   // 3 is dual prime in both

class InterSliceDecoder {
 public:
  InterSliceDecoder(const PictureParams& pp, const InterParams& ip, const std::uint8_t* begin, const std::uint8_t* end,
                    std::size_t offset, const SliceOutput& out)
      : pp_(pp),
        ip_(ip),
        t_(vlcTables()),
        it_(interVlcTables()),
        mc_(ip.mc ? *ip.mc : scalarMcKernels()),
        br_(begin, end),
        offset_(offset),
        out_(out),
        tracing_(out.trace != nullptr),
        scan_(ip.scanSlots) {
    frame_ = ip.pictureStructure == 3;
    for (int s = 0; s < 2; ++s) {
      fValid_[s] = ip.fCode[s][0] >= 1 && ip.fCode[s][0] <= 9 && ip.fCode[s][1] >= 1 && ip.fCode[s][1] <= 9;
    }
    parity_ = ip.pictureStructure == 2 ? 1 : 0;
  }

  void run(int code);

 private:
  void issue(IssueKind kind, int mbX, int mbY) { out_.report->add(kind, offset_ + br_.bytePosition(), mbX, mbY); }
  void setQuantiserScale(int code) { scale_ = quantiserScale(pp_.mpeg1, pp_.qScaleType, code); }
  void resetDc() {
    const int reset = pp_.mpeg1 ? 128 : (1 << (7 + pp_.intraDcPrecision));
    dcPred_[0] = dcPred_[1] = dcPred_[2] = reset;
  }
  void resetPmv(int s) {
    for (auto& r : pmv_) r[s][0] = r[s][1] = 0;
  }
  PredictionRef refOf(int s, int srcField) const {
    if (s == 1) return PredictionRef::kBackward;
    if (!frame_ && ip_.codingType == 2 && ip_.secondField && srcField != parity_) return PredictionRef::kCurrent;
    return PredictionRef::kForward;
  }
  void addOp(PredictionRef ref, int srcField, int dstField, int top, int height, bool average, int mvx, int mvy) {
    PredictionOp& op = mb_.ops[mb_.opCount++];
    op.ref = ref;
    op.srcField = static_cast<std::int8_t>(srcField);
    op.dstField = static_cast<std::int8_t>(dstField);
    op.top = static_cast<std::uint8_t>(top);
    op.height = static_cast<std::uint8_t>(height);
    op.average = average;
    op.mvx = static_cast<std::int16_t>(mvx);
    op.mvy = static_cast<std::int16_t>(mvy);
  }
  // The zero-vector prediction of a P macroblock without motion (§7.6.3.5, §7.6.6.2).
  void zeroPrediction() { addOp(PredictionRef::kForward, frame_ ? -1 : parity_, -1, 0, 16, false, 0, 0); }
  bool vector(int s, int r, bool fieldFormat, int& mvx, int& mvy, int* dmv);
  bool motionVectors(int s, int motionType);
  bool concealmentVectors();
  // What every block of a macroblock reads: set up once per macroblock instead of once per block
  // (GCC reloaded each through `this` for every block).
  struct BlockTables {
    const DctCodeEntry* shortCodes;  // intra or non-intra short codes (B.14 or B.15)
    const DctCodeEntry* longCodes;   // 12..16-bit codes
    const DctCodeEobEntry* first;    // non-intra: the first code of a block ('1s' is run 0, level 1)
    const DctCodeEobEntry* next;     // non-intra: the codes after it
    const InterScanSlot* slots;      // intra or non-intra matrix
    int scale;                       // quantiser_scale
  };
  template <bool Intra, bool Mpeg1>
  bool parseBlock(BitReader& br, const BlockTables& bt, int b, IssueKind& why);
  template <bool Mpeg1>
  bool parseBlocks(bool intra, IssueKind& why);
  void predictAndStore(bool parsed);
  void skipped(int address);

  const PictureParams& pp_;
  const InterParams& ip_;
  const VlcTables& t_;
  const InterVlcTables& it_;
  const McKernels& mc_;
  BitReader br_;
  std::size_t offset_;
  const SliceOutput& out_;
  // The timing model's trace is wanted: the EE's reads (vdec_, fdec_) and the bit positions of the
  // macroblock are counted only then (a branch the whole slice takes the same way).
  bool tracing_;
  const InterScanSlots& scan_;
  bool frame_ = true;
  // Per direction: both f_codes are 1..9 (checked once per slice, not per vector: four compares
  // per vector, and the chain of them mispredicted ~12k times per decode of the bench clip).
  bool fValid_[2] = {};
  int parity_ = 0;  // a field picture's field: 0 top, 1 bottom
  int scale_ = 0;
  int dcPred_[3] = {128, 128, 128};
  int pmv_[2][2][2] = {};      // PMV[r][s][t] (§7.6.3.1)
  std::uint8_t prevType_ = 0;  // macroblock_type of the last coded macroblock (B skips repeat it)
  Macroblock mb_;
  // The EE's reads of the macroblock being parsed, for the timed BDEC flow (MacroblockBits).
  int vdec_ = 0;
  int fdec_ = 0;
  std::uint8_t skippedPredictions_ = 0;  // predictions of each skipped macroblock before this one
};

// One motion_vector(r, s) (§6.2.5.3) and its reconstruction (§7.6.3.1); a field-format vector of a
// frame picture predicts its vertical part from PMV / 2 and stores it back doubled.
bool InterSliceDecoder::vector(int s, int r, bool fieldFormat, int& mvx, int& mvy, int* dmv) {
  if (!fValid_[s]) return false;  // 15 (no vectors) or reserved
  const int fx = ip_.fCode[s][0];
  const int fy = ip_.fCode[s][1];
  int dx = 0;
  int dy = 0;
  int len = 0;
  if (!readMotionDelta(br_, t_, fx, dx)) return false;
  if (dmv) {
    dmv[0] = dmvectorOf(br_.peek(2), len);
    br_.skip(len);
  }
  if (!readMotionDelta(br_, t_, fy, dy)) return false;
  if (dmv) {
    dmv[1] = dmvectorOf(br_.peek(2), len);
    br_.skip(len);
  }
  // libmpeg: a VDEC per motion_code and per dmvector, an FDEC per motion_residual (r_size > 0 and
  // motion_code != 0, which is a delta != 0). Only the trace reads them.
  if (tracing_) {
    vdec_ += dmv ? 4 : 2;
    fdec_ += (fx > 1 && dx != 0 ? 1 : 0) + (fy > 1 && dy != 0 ? 1 : 0);
  }
  const bool halfVertical = fieldFormat && frame_;
  mvx = wrapVector(pmv_[r][s][0], dx, fx);
  mvy = wrapVector(halfVertical ? pmv_[r][s][1] >> 1 : pmv_[r][s][1], dy, fy);
  pmv_[r][s][0] = mvx;
  pmv_[r][s][1] = halfVertical ? mvy * 2 : mvy;
  return true;
}

// motion_vectors(s) of one direction and the predictions they make (§6.2.5.2, §7.6.3, §7.6.4).
bool InterSliceDecoder::motionVectors(int s, int motionType) {
  const bool average = s == 1 && (mb_.type & kMbForward);
  int mvx = 0;
  int mvy = 0;
  if (pp_.mpeg1) {
    // 11172-2 §2.4.4.2: one frame vector, in whole samples with full_pel_*_vector.
    if (!vector(s, 0, false, mvx, mvy, nullptr)) return false;
    const int shift = ip_.fullPel[s] ? 1 : 0;
    addOp(refOf(s, -1), -1, -1, 0, 16, average, mvx * (1 << shift), mvy * (1 << shift));
    return true;
  }
  if (frame_) {
    if (motionType == kMotionFrame) {
      if (!vector(s, 0, false, mvx, mvy, nullptr)) return false;
      pmv_[1][s][0] = mvx;
      pmv_[1][s][1] = mvy;
      addOp(refOf(s, -1), -1, -1, 0, 16, average, mvx, mvy);
    } else if (motionType == kMotionField) {
      for (int r = 0; r < 2; ++r) {
        const int sel = static_cast<int>(br_.read(1));
        ++fdec_;
        if (!vector(s, r, true, mvx, mvy, nullptr)) return false;
        addOp(refOf(s, sel), sel, r, 0, 8, average, mvx, mvy);
      }
    } else {  // dual prime (§7.6.3.6): P pictures only
      if (s != 0 || ip_.codingType != 2) return false;
      int dmv[2];
      if (!vector(s, 0, true, mvx, mvy, dmv)) return false;
      pmv_[1][s][0] = pmv_[0][s][0];
      pmv_[1][s][1] = pmv_[0][s][1];
      // Each field from the opposite-parity field with the derived vector, averaged with the
      // same-parity prediction.
      const int mTop = ip_.topFieldFirst ? 1 : 3;
      const int mBottom = ip_.topFieldFirst ? 3 : 1;
      addOp(PredictionRef::kForward, 1, 0, 0, 8, false, dualPrimeScale(mvx, mTop) + dmv[0],
            dualPrimeScale(mvy, mTop) + dmv[1] - 1);
      addOp(PredictionRef::kForward, 0, 1, 0, 8, false, dualPrimeScale(mvx, mBottom) + dmv[0],
            dualPrimeScale(mvy, mBottom) + dmv[1] + 1);
      addOp(PredictionRef::kForward, 0, 0, 0, 8, true, mvx, mvy);
      addOp(PredictionRef::kForward, 1, 1, 0, 8, true, mvx, mvy);
    }
    return true;
  }
  // Field pictures.
  if (motionType == kMotionField) {
    const int sel = static_cast<int>(br_.read(1));
    ++fdec_;
    if (!vector(s, 0, true, mvx, mvy, nullptr)) return false;
    pmv_[1][s][0] = mvx;
    pmv_[1][s][1] = mvy;
    addOp(refOf(s, sel), sel, -1, 0, 16, average, mvx, mvy);
  } else if (motionType == kMotion16x8) {
    for (int r = 0; r < 2; ++r) {
      const int sel = static_cast<int>(br_.read(1));
      ++fdec_;
      if (!vector(s, r, true, mvx, mvy, nullptr)) return false;
      addOp(refOf(s, sel), sel, -1, 8 * r, 8, average, mvx, mvy);
    }
  } else {
    if (s != 0 || ip_.codingType != 2) return false;
    int dmv[2];
    if (!vector(s, 0, true, mvx, mvy, dmv)) return false;
    pmv_[1][s][0] = mvx;
    pmv_[1][s][1] = mvy;
    const int other = 1 - parity_;
    addOp(refOf(0, parity_), parity_, -1, 0, 16, false, mvx, mvy);
    addOp(refOf(0, other), other, -1, 0, 16, true, dualPrimeScale(mvx, 1) + dmv[0],
          dualPrimeScale(mvy, 1) + dmv[1] + (parity_ ? 1 : -1));
  }
  return true;
}

// The forward vector and marker bit of an intra macroblock with concealment_motion_vectors: they
// only set the vector predictors (§7.6.3.4); a decoder may use them to conceal lost data.
bool InterSliceDecoder::concealmentVectors() {
  if (!frame_) br_.skip(1);  // motion_vertical_field_select[0][0]
  fdec_ += frame_ ? 1 : 2;   // the field select and the marker bit
  int mvx = 0;
  int mvy = 0;
  if (!vector(0, 0, false, mvx, mvy, nullptr)) return false;
  pmv_[1][0][0] = mvx;
  pmv_[1][0][1] = mvy;
  br_.skip(1);  // marker_bit
  return !br_.overrun();
}

// The coded blocks of the macroblock. The reader lives in registers for them (a member would be
// stored and reloaded after every coefficient: a store-to-load round trip on the serial chain of
// codes), as in the intra slice decoder (ipu/slice_decoder.cpp).
template <bool Mpeg1>
bool InterSliceDecoder::parseBlocks(bool intra, IssueKind& why) {
  BitReader br = br_;
  bool ok = true;
  std::memset(mb_.rowMask, 0, sizeof mb_.rowMask);
  std::memset(mb_.colMask, 0, sizeof mb_.colMask);
  const BlockTables bt{t_.dctShort[(intra && !Mpeg1 && pp_.intraVlcFormat) ? 1 : 0],
                       t_.dctLong,
                       t_.dctNonIntra[0],
                       t_.dctNonIntra[1],
                       scan_[intra ? 1 : 0].data(),
                       scale_};
  // The coded blocks one by one, the next from the highest pattern bit left (bit 5 is block 0):
  // one branch on the count instead of one on every block's bit, which a busy P or B picture
  // makes unpredictable.
  for (unsigned pattern = mb_.pattern & 0x3Fu; pattern != 0 && ok;) {
    const int b = std::countl_zero(pattern) - 26;
    pattern &= ~(32u >> b);
    ok = intra ? parseBlock<true, Mpeg1>(br, bt, b, why) : parseBlock<false, Mpeg1>(br, bt, b, why);
  }
  br_ = br;
  return ok;
}

// One block's coefficients (§7.2, §7.3, §7.4): intra with its DC differential, or non-intra whose
// first code may be '1s' (run 0, level 1). Leaves the IDCT's masks and flags (ipu/kernels.hpp) in
// mb_.rowMask / mb_.colMask.
template <bool Intra, bool Mpeg1>
[[gnu::always_inline]] inline bool InterSliceDecoder::parseBlock(BitReader& br, const BlockTables& bt, int b,
                                                                 IssueKind& why) {
  std::int16_t* blk = mb_.block[b];
  unsigned parity = 0;
  unsigned masks = 0;
  int i = -1;
  if constexpr (Intra) {
    const int cc = b < 4 ? 0 : b - 3;
    const VlcEntry e = cc == 0 ? t_.dcSizeLuma[br.peek(9)] : t_.dcSizeChroma[br.peek(10)];
    if (e.len == 0) {
      why = IssueKind::kBadVlc;
      return false;
    }
    br.skip(e.len);
    const int size = static_cast<unsigned char>(e.value);
    if (size != 0) {
      const int bits = static_cast<int>(br.read(size));
      // §7.2.1: a differential below half its range is negative, bits - (2^size - 1); the offset by a
      // mask, as a branch on the sign was a coin toss.
      dcPred_[cc] += bits - (((1 << size) - 1) & (((bits >> (size - 1)) & 1) - 1));
    }
    int dc = Mpeg1 ? dcPred_[cc] * 8 : dcPred_[cc] * (1 << (3 - pp_.intraDcPrecision));
    dc = dc < -2048 ? -2048 : (dc > 2047 ? 2047 : dc);
    blk[0] = static_cast<std::int16_t>(dc);
    parity = static_cast<unsigned>(dc);
    i = 0;
  }
  const DctCodeEntry* shortCodes = bt.shortCodes;
  const DctCodeEntry* longCodes = bt.longCodes;
  const DctCodeEobEntry* codes = bt.first;
  const InterScanSlot* slots = bt.slots;
  const int scale = bt.scale;
  constexpr int k = Intra ? 0 : 1;  // the non-intra (2 QF + sign(QF)) term
  // Places the coefficient (2 x magnitude + k) x weight x scale at the slot; signMask is 0 or -1.
  auto placeAt = [&](const InterScanSlot& slot, int twoLevel, int signMask) {
    int v;
    if constexpr (Mpeg1) {
      // 11172-2 §2.4.4.1-2.4.4.3: then towards an odd value.
      v = (twoLevel * scale * slot.weight) >> 4;
      if ((v & 1) == 0 && v != 0) v -= 1;
    } else {
      v = (twoLevel * slot.weight * scale) >> 5;  // §7.4.2.3
    }
    // §7.4.3 saturation to [-2048, 2047], applied to the magnitude before the sign.
    const int limit = 2047 - signMask;
    v = v > limit ? limit : v;
    v = (v ^ signMask) - signMask;
    blk[slot.pos] = static_cast<std::int16_t>(v);
    parity ^= static_cast<unsigned>(v);
    masks |= slot.mask;
  };
  // Places the coefficient of magnitude mag at scan position i; false if i is past the block.
  auto place = [&](int mag, int negative) {
    if (i > 63) [[unlikely]]
      return false;
    placeAt(slots[i], 2 * mag + k, -negative);
    return true;
  };
  // A non-intra table's signed +-(2 x level + 1).
  auto placeSigned = [&](const InterScanSlot& slot, int level) {
    const int signMask = level >> 31;
    placeAt(slot, (level ^ signMask) - signMask, signMask);
  };
  // Past the slice's bytes the reader yields zeros, which are no code of either table, so the loop
  // ends within 16 bits; the caller checks for overrun once per macroblock.
  bool done = false;
  while (!done) {
    br.topUp();  // at least 56 bits
    int n = 0;
    if constexpr (!Intra) {
      // Up to four codes (code, sign and EOB at most 11 bits each) need no look at the bit count;
      // the first of a block in the table with '1s' for run 0, level 1.
      for (; n < 4; ++n) {
        const DctCodeEobEntry e = codes[br.peek(VlcTables::kDctShortBits)];
        codes = bt.next;
        if (e.level == 0) {
          // An end of block alone (after a code too long to share the lookup with it), or any
          // other symbol: one at a time below.
          if (e.eob) {
            br.skipUnchecked(e.bits);
            done = true;
          }
          break;
        }
        i += e.step;
        if (i > 63) [[unlikely]] {
          // Reported after the code, as before: the EOB after it ('10', 2 bits) is not read.
          br.skipUnchecked(e.bits - 2 * e.eob);
          why = IssueKind::kCoefficientOverrun;
          return false;
        }
        br.skipUnchecked(e.bits);
        placeSigned(slots[i], e.level);
        if (e.eob) {
          done = true;
          break;
        }
      }
      if (done) break;
      if (n == 4) continue;
    }
    // Up to four short codes (code and sign at most 11 bits each) need no look at the bit count;
    // for non-intra blocks, one symbol after the lookups above (at most three of them, 33 bits).
    DctCodeEntry s{};
    for (; n < 4; ++n) {
      s = shortCodes[br.peek(VlcTables::kDctShortBits)];
      if (s.level == 0) [[unlikely]]
        break;
      br.skipUnchecked(s.bits);
      i += s.step;
      if (!place(s.level, s.negative)) {
        why = IssueKind::kCoefficientOverrun;
        return false;
      }
      if constexpr (!Intra) break;
    }
    if (s.level != 0) continue;
    // Any other symbol; at least 56 - 3 * 11 = 23 bits are left.
    if (s.step == kDctKindLong) {
      // 12..16 bits and the sign: seven zeros, so the next 17 bits are the index.
      s = longCodes[br.peek(VlcTables::kDctLongBits)];
      if (s.level == 0) {
        why = IssueKind::kBadVlc;
        return false;
      }
      br.skipUnchecked(s.bits);
      i += s.step;
      if (!place(s.level, s.negative)) {
        why = IssueKind::kCoefficientOverrun;
        return false;
      }
    } else if (s.step == kDctKindEob) {
      br.skipUnchecked(s.bits);
      done = true;
    } else if (s.step == kDctKindEscape) {
      // skip() and read() refill as they go.
      int run = 0;
      const int level = readEscapeLevel<Mpeg1>(br, run);
      const int negative = level < 0;
      i += run + 1;
      if (!place(negative ? -level : level, negative)) {
        why = IssueKind::kCoefficientOverrun;
        return false;
      }
    } else {
      why = IssueKind::kBadVlc;
      return false;
    }
  }
  // The callers' reads refill when the count is low; restore that invariant.
  if (br.bitsCached() < 32) br.topUp();
  unsigned rowMask = (masks & 0xFF) | (Intra ? 1u : 0u);
  unsigned colMask = (masks >> 8) | (Intra ? 1u : 0u);
  if (!Mpeg1 && (parity & 1) == 0) {  // §7.4.4 mismatch control
    blk[63] = static_cast<std::int16_t>(blk[63] ^ 1);
    if (((rowMask | colMask) & 0x80) == 0) {
      rowMask |= kIdctToggleOnly;  // F[7][7] = +-1 alone in its row and column
    } else {
      rowMask |= 0x80;
      colMask |= 0x80;
    }
  }
  // The only coded coefficient was the first in scan order (the decoders' DC shortcut): a non-intra
  // block's first code is a coefficient and scan positions only grow, so the last one at 0 is it.
  if (!Intra && i == 0) rowMask |= kIdctFirstOnly;
  mb_.rowMask[b] = static_cast<std::uint16_t>(rowMask);
  mb_.colMask[b] = static_cast<std::uint8_t>(colMask);
  return true;
}

void InterSliceDecoder::predictAndStore(bool parsed) {
  const PredictionResult r = predictMacroblock(mb_, ip_.refs, pp_, mc_);
  if (r.clamped) issue(IssueKind::kBadMotionVector, mb_.mbX, mb_.mbY);
  if (r.missingReference) ++out_.report->macroblocksConcealed;
  if (parsed) reconstructBlocks(mb_, pp_);
  (*out_.decoded)[static_cast<std::size_t>(mb_.mbY) * static_cast<std::size_t>(out_.decodedStride) +
                  static_cast<std::size_t>(mb_.mbX)] = 1;
}

// A skipped macroblock (§7.6.6): P pictures predict with a zero vector and reset the vector
// predictors; B pictures repeat the previous macroblock's directions and vectors (frame-based in
// frame pictures, from the same-parity field in field pictures).
void InterSliceDecoder::skipped(int address) {
  mb_.mbX = address % pp_.mbWidth;
  mb_.mbY = address / pp_.mbWidth;
  mb_.type = 0;
  mb_.skipped = true;
  mb_.fieldDct = false;
  mb_.opCount = 0;
  mb_.pattern = 0;
  if (ip_.codingType == 2) {
    resetPmv(0);
    zeroPrediction();
  } else {
    const std::uint8_t dirs = prevType_ & (kMbForward | kMbBackward);
    if (dirs == 0) {
      issue(IssueKind::kBadMacroblockAddress, mb_.mbX, mb_.mbY);  // a skip after an intra macroblock
      zeroPrediction();
    }
    const int src = frame_ ? -1 : parity_;
    for (int s = 0; s < 2; ++s) {
      if (!(dirs & (s ? kMbBackward : kMbForward))) continue;
      const int shift = pp_.mpeg1 && ip_.fullPel[s] ? 1 : 0;
      mb_.type |= s ? kMbBackward : kMbForward;
      addOp(s ? PredictionRef::kBackward : PredictionRef::kForward, src, -1, 0, 16, s == 1 && (dirs & kMbForward),
            pmv_[0][s][0] * (1 << shift), pmv_[0][s][1] * (1 << shift));
    }
  }
  skippedPredictions_ = static_cast<std::uint8_t>(mb_.opCount);
  predictAndStore(false);
}

void InterSliceDecoder::run(int code) {
  const SliceHeader h = readSliceHeader(br_, pp_, code);
  const int row = h.row;
  if (!h.ok) {
    issue(h.why, -1, row);
    return;
  }
  int qsc = h.quantiserScaleCode;
  setQuantiserScale(qsc);
  resetDc();
  std::memset(pmv_, 0, sizeof pmv_);
  std::memset(mb_.block, 0, sizeof mb_.block);

  const int total = pp_.mbWidth * pp_.mbRows;
  int address = row * pp_.mbWidth - 1;
  bool first = true;
  std::size_t mbStart = 0;
  // The column and row of `address`, kept by adding the increments: two integer divisions per
  // macroblock were ~0.4 % of the decode.
  int mbX = -1;
  int mbY = row;
  for (;;) {
    int inc = 0;
    if (!readAddressIncrement(br_, t_, inc)) {
      const bool atEnd = mbX + 1 == pp_.mbWidth;
      issue(br_.overrun() ? IssueKind::kTruncatedSlice : IssueKind::kBadVlc, atEnd ? 0 : mbX + 1,
            atEnd ? mbY + 1 : mbY);
      return;
    }
    // libmpeg: one VDEC per address increment code (escapes included) and one for macroblock_type.
    if (tracing_) vdec_ = 2 + (inc - 1) / 33;
    fdec_ = 0;
    const int skippedBefore = first ? 0 : inc - 1;
    if (!first && inc > 1) {
      resetDc();
      for (int k = 1; k < inc; ++k) {
        const int a = address + k;
        if (a >= total || (!pp_.mpeg1 && a / pp_.mbWidth != row)) {
          issue(IssueKind::kBadMacroblockAddress, a % pp_.mbWidth, a / pp_.mbWidth);
          return;
        }
        skipped(a);
      }
    }
    address += inc;
    first = false;
    mbX += inc;
    if (mbX >= pp_.mbWidth) [[unlikely]] {
      mbY += mbX / pp_.mbWidth;
      mbX %= pp_.mbWidth;
    }
    if (address >= total || (!pp_.mpeg1 && mbY != row)) {
      issue(IssueKind::kBadMacroblockAddress, mbX, mbY);
      return;
    }
    mb_.mbX = mbX;
    mb_.mbY = mbY;
    mb_.skipped = false;
    mb_.opCount = 0;
    const InterVlcEntry type = (ip_.codingType == 2 ? it_.mbTypeP : it_.mbTypeB)[br_.peek(6)];
    if (type.len == 0) {
      issue(IssueKind::kBadVlc, mbX, mbY);
      return;
    }
    br_.skip(type.len);
    mb_.type = type.value;
    const bool intra = (type.value & kMbIntra) != 0;
    int motionType = kMotionFrame;
    if (!pp_.mpeg1 && (type.value & (kMbForward | kMbBackward))) {
      if (!frame_ || !ip_.framePredFrameDct) {
        motionType = static_cast<int>(br_.read(2));
        ++fdec_;
      }
      if (motionType == 0) {
        issue(IssueKind::kBadVlc, mbX, mbY);  // reserved motion type
        return;
      }
    }
    mb_.fieldDct = false;
    if (pp_.fieldDctAllowed && (intra || (type.value & kMbPattern))) {
      mb_.fieldDct = br_.readBit();
      ++fdec_;
    }
    if (mb_.fieldDct) ++out_.report->fieldDctMacroblocks;
    if (type.value & kMbQuant) {
      qsc = static_cast<int>(br_.read(5));
      ++fdec_;
      if (qsc == 0) {
        issue(IssueKind::kBadHeader, mbX, mbY);
        return;
      }
      setQuantiserScale(qsc);
    }
    bool ok = true;
    std::size_t blockStart = 0;
    if (intra) {
      if (pp_.concealmentMotionVectors) {
        ok = concealmentVectors();
      } else {
        std::memset(pmv_, 0, sizeof pmv_);
      }
      mb_.pattern = 0x3F;
      if (tracing_) blockStart = br_.position();
    } else {
      resetDc();
      if (ip_.codingType == 2 && !(type.value & kMbForward)) {
        resetPmv(0);
        zeroPrediction();  // "No MC"
      }
      if (type.value & kMbForward) ok = motionVectors(0, motionType);
      if (ok && (type.value & kMbBackward)) ok = motionVectors(1, motionType);
      mb_.pattern = 0;
      if (tracing_) blockStart = br_.position();
      if (ok && (type.value & kMbPattern)) {
        const InterVlcEntry cbp = it_.codedBlockPattern[br_.peek(9)];
        ok = cbp.len != 0;
        br_.skip(cbp.len);
        mb_.pattern = cbp.value;
      }
    }
    if (!ok) {
      issue(br_.overrun() ? IssueKind::kTruncatedSlice : IssueKind::kBadVlc, mbX, mbY);
      return;
    }
    IssueKind why = IssueKind::kBadVlc;
    if (!(pp_.mpeg1 ? parseBlocks<true>(intra, why) : parseBlocks<false>(intra, why))) {
      if (br_.overrun()) why = IssueKind::kTruncatedSlice;
      issue(why, mbX, mbY);
      std::memset(mb_.block, 0, sizeof mb_.block);
      return;
    }
    if (br_.overrun()) {
      issue(IssueKind::kTruncatedSlice, mbX, mbY);
      std::memset(mb_.block, 0, sizeof mb_.block);
      return;
    }
    prevType_ = mb_.type;
    predictAndStore(true);
    if (tracing_) {
      const std::size_t end = br_.position();
      recordMacroblock(out_.trace, address, end, mbStart, offset_);
      MacroblockBits& r = out_.trace->back();
      r.vdec = static_cast<std::uint8_t>(std::min(vdec_, 255));
      r.fdec = static_cast<std::uint8_t>(std::min(fdec_, 255));
      r.bdec = intra || mb_.pattern != 0;
      r.blockBits = r.bdec ? static_cast<std::uint32_t>(end - blockStart) : 0;
      r.predictions = static_cast<std::uint8_t>(mb_.opCount);
      r.averaged = static_cast<std::uint8_t>(
          std::count_if(mb_.ops, mb_.ops + mb_.opCount, [](const PredictionOp& op) { return op.average; }));
      r.skippedBefore = static_cast<std::uint16_t>(std::min(skippedBefore, 65535));
      r.skippedPredictions = skippedPredictions_;
    }
    if (br_.peek(23) == 0) return;
  }
}

}  // namespace

void prepareScanSlots(InterParams& ip, const PictureParams& pp) {
  for (int i = 0; i < 64; ++i) {
    const int pos = pp.scan[i];
    const auto mask = static_cast<std::uint16_t>((1u << (pos >> 3)) | (1u << (8 + (pos & 7))));
    ip.scanSlots[0][i] = {ip.nonIntraMatrix[pos], static_cast<std::uint8_t>(pos), mask};
    ip.scanSlots[1][i] = {pp.intraMatrix[pos], static_cast<std::uint8_t>(pos), mask};
  }
}

void decodeInterSlice(const PictureParams& pp, const InterParams& ip, int code, const std::uint8_t* begin,
                      const std::uint8_t* end, std::size_t offset, const SliceOutput& out) {
  InterSliceDecoder d(pp, ip, begin, end, offset, out);
  d.run(code);
}

}  // namespace vbim::ipu
