#include "ipu/motion_vectors.hpp"

#include <cstdint>

#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {

bool readMotionDelta(BitReader& br, int fCode, int& delta) {
  const VlcEntry e = vlcTables().motionCode[br.peek(11)];
  if (e.len == 0) return false;
  br.skip(e.len);
  // The table holds motion_code as a signed byte, -16..16; its magnitude and sign.
  const int code = e.value < 0 ? -static_cast<int>(static_cast<std::uint8_t>(-e.value))
                               : static_cast<int>(static_cast<std::uint8_t>(e.value));
  const int rSize = fCode - 1;
  if (rSize == 0 || code == 0) {
    delta = code;
    return true;
  }
  const int residual = static_cast<int>(br.read(rSize));
  const int magnitude = ((code < 0 ? -code : code) - 1) * (1 << rSize) + residual + 1;
  delta = code < 0 ? -magnitude : magnitude;
  return true;
}

}  // namespace vbim::ipu
