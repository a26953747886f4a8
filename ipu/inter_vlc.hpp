// The variable-length codes only prediction-coded pictures use (ISO/IEC 13818-2 Annex B; the same
// codes in 11172-2 Annex 2.B): macroblock_type in P and B pictures (B.3, B.4), coded_block_pattern
// (B.9) and dmvector (B.11), as data expanded into direct lookup tables. B.1, B.2, B.10 and the DCT
// tables are in vlc_tables.hpp.
#pragma once

#include <cstdint>

namespace vbim::ipu {

// macroblock_type flags (Table 6-? "macroblock_type" columns).
inline constexpr std::uint8_t kMbQuant = 1;
inline constexpr std::uint8_t kMbForward = 2;   // macroblock_motion_forward
inline constexpr std::uint8_t kMbBackward = 4;  // macroblock_motion_backward
inline constexpr std::uint8_t kMbPattern = 8;   // macroblock_pattern
inline constexpr std::uint8_t kMbIntra = 16;

// One code: its length in bits (0 = no such code) and its value (flags, or the pattern).
struct InterVlcEntry {
  std::uint8_t value;
  std::uint8_t len;
};

struct InterVlcTables {
  InterVlcEntry mbTypeP[1 << 6];            // B.3, next 6 bits
  InterVlcEntry mbTypeB[1 << 6];            // B.4, next 6 bits
  InterVlcEntry codedBlockPattern[1 << 9];  // B.9, next 9 bits; value bit 5 = block 0 .. bit 0 = block 5
};

const InterVlcTables& interVlcTables();

// B.11 dmvector: '0' = 0, '10' = +1, '11' = -1. `bits` are the next two bits; sets len.
inline int dmvectorOf(std::uint32_t bits, int& len) {
  if ((bits & 2) == 0) {
    len = 1;
    return 0;
  }
  len = 2;
  return (bits & 1) ? -1 : 1;
}

}  // namespace vbim::ipu
