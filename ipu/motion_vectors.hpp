// Motion vector decoding (ISO/IEC 13818-2 §6.2.5.2-6.2.5.3, §7.6.3; 11172-2 §2.4.4.2): the
// motion_code / motion_residual pair, the prediction from PMV with its wrap into the f_code range,
// and the dual-prime derived vectors (§7.6.3.6).
#pragma once

#include <cstdint>

#include "ipu/bit_reader.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {

// Reads motion_code (B.10) and, if present, motion_residual, and returns the differential
// (§7.6.3.1: delta). `fCode` 1..9. False on an invalid code.
// Inline, with the tables passed in: it runs twice per vector on the P/B parse's serial chain.
inline bool readMotionDelta(BitReader& br, const VlcTables& t, int fCode, int& delta) {
  const VlcEntry e = t.motionCode[br.peek(11)];
  if (e.len == 0) return false;
  br.skip(e.len);
  // The table holds motion_code as a signed byte, -16..16.
  const int code = e.value;
  const int rSize = fCode - 1;
  if (rSize == 0 || code == 0) {
    delta = code;
    return true;
  }
  const int residual = static_cast<int>(br.read(rSize));
  // The sign by a mask, not a branch: a vector's direction is data (cachegrind counted 18k
  // mispredictions per decode of the bench clip on the branches this replaces).
  const int sign = code >> 31;
  const int magnitude = (((code ^ sign) - sign) - 1) * (1 << rSize) + residual + 1;
  delta = (magnitude ^ sign) - sign;
  return true;
}
inline bool readMotionDelta(BitReader& br, int fCode, int& delta) {
  return readMotionDelta(br, vlcTables(), fCode, delta);
}

// §7.6.3.1: prediction + delta, brought into [-16 f, 16 f - 1] with f = 2^(fCode - 1) by adding or
// subtracting 32 f.
inline int wrapVector(int prediction, int delta, int fCode) {
  const int f = 1 << (fCode - 1);
  int v = prediction + delta;
  if (v < -16 * f) v += 32 * f;
  if (v > 16 * f - 1) v -= 32 * f;
  return v;
}

// v * m // 2 of §7.6.3.6: the half rounded away from zero.
inline int dualPrimeScale(int v, int m) {
  const int p = v * m;
  return p >= 0 ? (p + 1) >> 1 : -((-p + 1) >> 1);
}

}  // namespace vbim::ipu
