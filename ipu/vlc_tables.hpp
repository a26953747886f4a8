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

// Meanings of the special DCT coefficient codes in the tables of B.14 / B.15 as data.
inline constexpr std::int16_t kDctEob = -1;
inline constexpr std::int16_t kDctEscape = -2;

// A run/level code of B.14 / B.15 together with its sign bit, for the hot AC loop: one load gives
// everything needed to consume it and place the coefficient. level == 0 marks the other symbols
// (`step` then holds their kind) in the short table.
struct DctCodeEntry {
  std::uint8_t bits;      // code + sign bits to consume (for kEob the code alone)
  std::uint8_t step;      // run + 1: scan positions to advance; or the kind when level == 0
  std::uint8_t level;     // magnitude 1..40; 0: not a run/level code of this table
  std::uint8_t negative;  // 1 if the sign bit is set
};
inline constexpr std::uint8_t kDctKindInvalid = 0;
inline constexpr std::uint8_t kDctKindEob = 1;
inline constexpr std::uint8_t kDctKindEscape = 2;
inline constexpr std::uint8_t kDctKindLong = 3;  // 12..16-bit code: look it up in dctLong

// A run/level code of B.14 with its sign, and the end of block after it when that fits in the
// same kDctShortBits bits, for the non-intra AC loop: most non-intra blocks hold one to three
// coefficients, so the end of a block is found with its last code, in one lookup (and the
// '1s' form of a block's first code in its own table instead of a branch on the first bit).
// level == 0: an end of block alone (eob = 1), or a symbol to look up in dctShort[0].
struct DctCodeEobEntry {
  std::uint8_t bits;  // bits of the code with its sign, and of the EOB if eob = 1
  std::uint8_t step;  // run + 1
  std::int8_t level;  // +-(2 x level + 1): the non-intra term of §7.4.2.3 with its sign; 0: none
  std::uint8_t eob;   // 1: an end of block follows the code (its bits are in `bits`)
};

// One or two run/level codes of B.14 / B.15 with their signs, and the end of block after them when
// it fits, read from the next kDctPairBits bits in one lookup, for the intra AC loop: the codes of
// a block are a serial chain (each code's length decides where the next begins), so taking two a
// lookup halves the chain where a smooth lightmap's short codes come in pairs. step1 == 0: the next
// symbol is no run/level code of the short table (an end of block alone, an escape, a long code or
// an invalid one): look it up in dctShort. step2 == 0: one code only (level2 is then 0).
struct DctPairEntry {
  std::uint8_t bits;   // bits to consume: both codes with their signs, and the EOB if eob = 1
  std::uint8_t step1;  // run + 1 of the first code; 0: none (see above)
  std::uint8_t level1;
  std::uint8_t negative1;
  std::uint8_t step2;  // run + 1 of the second code; 0: none
  std::uint8_t level2;
  std::uint8_t negative2;
  std::uint8_t eob;  // 1: an end of block follows (its bits are in `bits`)
};

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
  // B.14 (table zero, intra AC) and B.15 (table one), intra_vlc_format = 0 / 1.
  // The run/level codes of up to kDctShortBits - 1 bits plus their sign, on the next kDctShortBits
  // bits, and the kind of every other symbol (EOB, escape, long code, invalid).
  static constexpr int kDctShortBits = 11;
  DctCodeEntry dctShort[2][1 << kDctShortBits];
  // The 12..16-bit codes (shared by both tables) plus their sign: they all begin with seven zero
  // bits, so the next 17 bits, read as a number, are below 2^10 and index this table directly.
  static constexpr int kDctLongBits = 17;
  DctCodeEntry dctLong[1 << 10];
  // B.14 / B.15 (as dctShort) in pairs for intra blocks, on the next kDctPairBits bits.
  static constexpr int kDctPairBits = 11;  // 12 was slower in the play (32 KiB a table)
  DctPairEntry dctPairs[2][1 << kDctPairBits];
  // B.14 for non-intra blocks on the next kDctShortBits bits: [0] for the first code of a block
  // ('1s' for run 0, level 1), [1] after it ('11s').
  DctCodeEobEntry dctNonIntra[2][1 << kDctShortBits];
};

const VlcTables& vlcTables();

}  // namespace vbim::ipu
