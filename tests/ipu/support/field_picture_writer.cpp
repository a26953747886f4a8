#include "tests/ipu/support/field_picture_writer.hpp"

#include <algorithm>
#include <stdexcept>

#include "ipu/motion_vectors.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu::testing {
namespace {

class BitWriter {
 public:
  void put(std::uint32_t value, int bits) {
    for (int i = bits - 1; i >= 0; --i) {
      acc_ = static_cast<std::uint8_t>((acc_ << 1) | ((value >> i) & 1));
      if (++n_ == 8) flushByte();
    }
  }
  void startCode(std::uint8_t code) {
    while (n_ != 0) put(0, 1);
    for (std::uint8_t b : {std::uint8_t{0}, std::uint8_t{0}, std::uint8_t{1}, code}) put(b, 8);
  }
  std::vector<std::uint8_t> bytes() {
    while (n_ != 0) put(0, 1);
    return out_;
  }

 private:
  void flushByte() {
    out_.push_back(acc_);
    acc_ = 0;
    n_ = 0;
  }
  std::vector<std::uint8_t> out_;
  std::uint8_t acc_ = 0;
  int n_ = 0;
};

struct Rng {
  std::uint32_t s;
  int next(int lo, int hi) {  // [lo, hi]
    s = s * 1664525u + 1013904223u;
    return lo + static_cast<int>((s >> 8) % static_cast<std::uint32_t>(hi - lo + 1));
  }
};

// Table B.10 motion_code 0..16: length and code (the last bit is the sign, 0 here).
constexpr int kMotionLen[17] = {1, 3, 4, 5, 7, 8, 8, 8, 10, 10, 10, 11, 11, 11, 11, 11, 11};
constexpr int kMotionCode[17] = {0x1,  0x2,  0x2,  0x2,  0x6,  0xA,  0x8,  0x6, 0x16,
                                 0x14, 0x12, 0x22, 0x20, 0x1E, 0x1C, 0x1A, 0x18};

void motionCode(BitWriter& w, int delta) {  // f_code 1: the code is the delta, -16..16
  const int m = delta < 0 ? -delta : delta;
  w.put(static_cast<std::uint32_t>(kMotionCode[m] | (delta < 0 ? 1 : 0)), kMotionLen[m]);
}
void dmvector(BitWriter& w, int d) {
  if (d == 0) {
    w.put(0, 1);
  } else {
    w.put(d > 0 ? 2 : 3, 2);
  }
}
// A delta (motion_code, -16..16) that takes the predictor to v in the f_code 1 range [-16, 15].
int deltaFor(int v, int pred) {
  int d = v - pred;
  if (d > 16) d -= 32;
  if (d < -16) d += 32;
  return d;
}

class PictureWriter {
 public:
  PictureWriter(const FieldStreamOptions& o, BitWriter& w, Rng& rng) : o_(o), w_(w), rng_(rng) {}

  // structure: 1 top, 2 bottom, 3 frame.
  void picture(int temporalReference, int structure) {
    structure_ = structure;
    w_.startCode(0x00);
    w_.put(static_cast<std::uint32_t>(temporalReference), 10);
    w_.put(2, 3);  // P
    w_.put(0xFFFF, 16);
    w_.put(0, 1);  // full_pel_forward_vector
    w_.put(7, 3);  // forward_f_code
    w_.put(0, 1);  // extra_bit_picture
    w_.startCode(0xB5);
    w_.put(8, 4);
    w_.put(1, 4);  // f_code[0][0], [0][1]: 1
    w_.put(1, 4);
    w_.put(15, 4);
    w_.put(15, 4);
    w_.put(0, 2);  // intra_dc_precision
    w_.put(static_cast<std::uint32_t>(structure), 2);
    w_.put(1, 1);                              // top_field_first
    w_.put(0, 1);                              // frame_pred_frame_dct
    w_.put(o_.concealmentVectors ? 1 : 0, 1);  // concealment_motion_vectors
    w_.put(0, 1);                              // q_scale_type
    w_.put(0, 1);                              // intra_vlc_format
    w_.put(0, 1);                              // alternate_scan
    w_.put(0, 1);                              // repeat_first_field
    w_.put(0, 1);                              // chroma_420_type
    w_.put(0, 1);                              // progressive_frame
    w_.put(0, 1);                              // composite_display_flag
    const int mbw = o_.width / 16;
    const int rows = structure == 3 ? o_.height / 16 : o_.height / 32;
    for (int row = 0; row < rows; ++row) slice(row, mbw);
  }

 private:
  // Lines of the prediction source: a field (16 rows per field macroblock) or, for field
  // prediction in a frame picture, a field of 8 rows per macroblock row.
  bool legal(int mbX, int y0, int rows, int height, int mvx, int mvy) const {
    const int px = 32 * mbX + mvx;
    const int py = 2 * y0 + mvy;
    return px >= 0 && px <= 2 * (o_.width - 16) && py >= 0 && py <= 2 * (height - rows);
  }
  int pick(int lo, int hi) { return rng_.next(std::max(lo, -16), std::min(hi, 15)); }

  void slice(int row, int mbw) {
    w_.startCode(static_cast<std::uint8_t>(row + 1));
    w_.put(8, 5);  // quantiser_scale_code
    w_.put(0, 1);  // extra_bit_slice
    pmv_[0][0] = pmv_[0][1] = pmv_[1][0] = pmv_[1][1] = 0;
    int x = 0;
    bool first = true;
    const int fieldLines = o_.height / 2;
    while (x < mbw) {
      // A skipped macroblock now and then (never the first or last of a slice).
      if (!first && x + 1 < mbw && rng_.next(0, 5) == 0) {
        w_.put(3, 3);  // increment 2: one skipped macroblock, which resets the predictors
        pmv_[0][0] = pmv_[0][1] = pmv_[1][0] = pmv_[1][1] = 0;
        ++x;
      } else {
        w_.put(1, 1);  // increment 1
      }
      first = false;
      if (o_.concealmentVectors && rng_.next(0, 4) == 0) {
        intraMacroblock();
        ++x;
        continue;
      }
      const bool coded = rng_.next(0, 2) == 0;
      w_.put(1, coded ? 1 : 3);  // '1' MC coded, '001' MC not coded
      if (structure_ == 3) {
        frameMacroblock(x, row, fieldLines, coded);
      } else {
        fieldMacroblock(x, row, fieldLines);
      }
      if (coded) {
        w_.put(0x7, 3);  // coded_block_pattern 60: the four luma blocks
        for (int b = 0; b < 4; ++b) {
          w_.put(rng_.next(0, 1) ? 3 : 2, 2);  // '1s': run 0, level +-1
          w_.put(2, 2);                        // EOB
        }
      }
      ++x;
    }
  }

  // An intra macroblock ('00011') with its concealment vector (frame format in frame pictures,
  // field select and vector in field pictures; it sets both predictors) and six DC-only blocks.
  void intraMacroblock() {
    w_.put(3, 5);
    if (structure_ == 3) w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);  // dct_type
    if (structure_ != 3) w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);  // field select
    const int vx = rng_.next(-16, 15);
    const int vy = rng_.next(-16, 15);
    motionCode(w_, deltaFor(vx, pmv_[0][0]));
    motionCode(w_, deltaFor(vy, pmv_[0][1]));
    pmv_[0][0] = pmv_[1][0] = vx;
    pmv_[0][1] = pmv_[1][1] = vy;
    w_.put(1, 1);  // marker_bit
    for (int b = 0; b < 6; ++b) {
      if (b < 4) {
        w_.put(4, 3);  // dct_dc_size_luminance 0
      } else {
        w_.put(0, 2);  // dct_dc_size_chrominance 0
      }
      w_.put(2, 2);  // EOB
    }
  }

  // P field picture: field (01), 16x8 (10) or dual prime (11).
  void fieldMacroblock(int x, int row, int fieldLines) {
    int kind = rng_.next(0, o_.dualPrime ? 2 : 1);
    int mvx = pick(-32 * x, 2 * (o_.width - 16) - 32 * x);
    int mvy = pick(-32 * row, 2 * (fieldLines - 16) - 32 * row);
    int dmv[2] = {rng_.next(-1, 1), rng_.next(-1, 1)};
    const int parity = structure_ == 2 ? 1 : 0;
    if (kind == 2) {
      const int ox = dualPrimeScale(mvx, 1) + dmv[0];
      const int oy = dualPrimeScale(mvy, 1) + dmv[1] + (parity ? 1 : -1);
      if (!legal(x, 16 * row, 16, fieldLines, ox, oy)) kind = 0;
    }
    w_.put(static_cast<std::uint32_t>(kind == 0 ? 1 : (kind == 1 ? 2 : 3)), 2);
    if (kind == 0) {
      w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);  // motion_vertical_field_select
      vector(0, mvx, mvy, nullptr, false);
      pmv_[1][0] = pmv_[0][0];
      pmv_[1][1] = pmv_[0][1];
    } else if (kind == 1) {
      for (int r = 0; r < 2; ++r) {
        const int vx = pick(-32 * x, 2 * (o_.width - 16) - 32 * x);
        const int vy = pick(-(32 * row + 16 * r), 2 * (fieldLines - 8) - (32 * row + 16 * r));
        w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);
        vector(r, vx, vy, nullptr, false);
      }
    } else {
      vector(0, mvx, mvy, dmv, false);
      pmv_[1][0] = pmv_[0][0];
      pmv_[1][1] = pmv_[0][1];
    }
  }

  // P frame picture with frame_pred_frame_dct 0: dual prime (11) or field prediction (01).
  void frameMacroblock(int x, int row, int fieldLines, bool coded) {
    // libmpeg2 does not fold the vertical part of these field vectors into the f_code range
    // (§7.6.3.1 does): keep it within 16 of its prediction, where folding changes nothing.
    const int predY = pmv_[0][1] >> 1;
    int mvx = pick(-32 * x, 2 * (o_.width - 16) - 32 * x);
    int mvy = pick(std::max(-16 * row, predY - 16), std::min(2 * (fieldLines - 8) - 16 * row, predY + 16));
    int dmv[2] = {rng_.next(-1, 1), rng_.next(-1, 1)};
    bool dp = o_.dualPrime && rng_.next(0, 1) == 0;
    if (dp) {
      // Top field from the bottom one (m 1, e -1) and bottom from top (m 3, e +1): top field first.
      const int o1x = dualPrimeScale(mvx, 1) + dmv[0], o1y = dualPrimeScale(mvy, 1) + dmv[1] - 1;
      const int o2x = dualPrimeScale(mvx, 3) + dmv[0], o2y = dualPrimeScale(mvy, 3) + dmv[1] + 1;
      dp = legal(x, 8 * row, 8, fieldLines, o1x, o1y) && legal(x, 8 * row, 8, fieldLines, o2x, o2y);
    }
    w_.put(dp ? 3 : 1, 2);                                              // frame_motion_type
    if (coded) w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);  // dct_type
    if (dp) {
      vector(0, mvx, mvy, dmv, true);
      pmv_[1][0] = pmv_[0][0];
      pmv_[1][1] = pmv_[0][1];
    } else {
      for (int r = 0; r < 2; ++r) {
        const int vx = pick(-32 * x, 2 * (o_.width - 16) - 32 * x);
        const int py = pmv_[r][1] >> 1;
        const int vy = pick(std::max(-16 * row, py - 16), std::min(2 * (fieldLines - 8) - 16 * row, py + 16));
        w_.put(static_cast<std::uint32_t>(rng_.next(0, 1)), 1);
        vector(r, vx, vy, nullptr, true);
      }
    }
  }

  // motion_vector(r, 0) for the target vector (vx, vy); in a frame picture the vertical part is
  // a field vector predicted from PMV / 2 and kept doubled.
  void vector(int r, int vx, int vy, const int* dmv, bool frameField) {
    motionCode(w_, deltaFor(vx, pmv_[r][0]));
    if (dmv) dmvector(w_, dmv[0]);
    const int predY = frameField ? pmv_[r][1] >> 1 : pmv_[r][1];
    motionCode(w_, deltaFor(vy, predY));
    if (dmv) dmvector(w_, dmv[1]);
    pmv_[r][0] = vx;
    pmv_[r][1] = frameField ? vy * 2 : vy;
  }

  const FieldStreamOptions& o_;
  BitWriter& w_;
  Rng& rng_;
  int structure_ = 3;
  int pmv_[2][2] = {};
};

}  // namespace

std::vector<std::uint8_t> makeFieldStream(const FieldStreamOptions& o) {
  EncodeOptions e;
  e.width = o.width;
  e.height = o.height;
  e.frames = 1;
  e.interlacedDct = true;
  e.content = Content::kPan;
  e.seed = o.seed;
  std::vector<std::uint8_t> es = encodeIntra(e);
  // Drop the closing sequence_end_code; the P pictures follow the I frame.
  if (es.size() >= 4 && es[es.size() - 4] == 0 && es[es.size() - 3] == 0 && es[es.size() - 2] == 1 && es.back() == 0xB7)
    es.resize(es.size() - 4);
  BitWriter w;
  Rng rng{o.seed * 2654435761u + 99};
  PictureWriter pw(o, w, rng);
  for (int p = 0; p < o.pictures; ++p) {
    if (o.fieldPictures) {
      pw.picture(p + 1, 1);
      pw.picture(p + 1, 2);
    } else {
      pw.picture(p + 1, 3);
    }
  }
  w.startCode(0xB7);
  const std::vector<std::uint8_t> tail = w.bytes();
  es.insert(es.end(), tail.begin(), tail.end());
  return es;
}

}  // namespace vbim::ipu::testing
