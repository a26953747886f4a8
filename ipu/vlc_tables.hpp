// Variable-length code tables of ISO/IEC 13818-2 Annex B (same codes in 11172-2 Annex 2.B), kept as
// data (code length, code value, meaning) and expanded once into lookup tables for the decoder.
#pragma once

#include <cstdint>

namespace vbim::ipu {

// One decoded symbol of a direct-lookup table: `len` bits long (0 = no such code), value `value`.
struct VlcEntry {
  std::int8_t value;
  std::uint8_t len;
};

// DCT coefficient symbol (B.14 / B.15): run/level, or one of the specials. `len` excludes the sign.
struct DctEntry {
  std::uint8_t run;
  std::uint8_t len;    // 0: invalid code
  std::int16_t level;  // > 0 for run/level; kDctEob / kDctEscape / kDctSub for specials
};
inline constexpr std::int16_t kDctEob = -1;
inline constexpr std::int16_t kDctEscape = -2;
inline constexpr std::int16_t kDctSub = -3;  // first-level entry pointing at a second-level table

// Special values of the macroblock address increment table (B.1).
inline constexpr std::int8_t kMbaEscape = -1;    // '0000 0001 000': add 33
inline constexpr std::int8_t kMbaStuffing = -2;  // '0000 0001 111': MPEG-1 macroblock_stuffing

// Lookup tables, built on first use (thread-safe static initialisation).
struct VlcTables {
  VlcEntry mbAddressIncrement[1 << 11];  // B.1, indexed by the next 11 bits
  VlcEntry intraMbType[1 << 2];          // B.2 (I pictures), value bit 0 = quant; next 2 bits
  VlcEntry motionCode[1 << 11];          // B.10 including the sign bit, next 11 bits
  VlcEntry dcSizeLuma[1 << 9];           // B.12, next 9 bits
  VlcEntry dcSizeChroma[1 << 10];        // B.13, next 10 bits
  // B.14 (table zero, intra AC) and B.15 (table one): first level on the next kDctFirstBits bits
  // (every code up to 10 bits resolves there); entries with level == kDctSub point (run = index)
  // at a second-level table read on the following `len` bits (codes of 12 to 16 bits).
  static constexpr int kDctFirstBits = 10;
  DctEntry dct[2][1 << kDctFirstBits];
  DctEntry dctSub[2][8][64];
};

const VlcTables& vlcTables();

}  // namespace vbim::ipu
