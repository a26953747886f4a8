#include "ipu/vlc_tables.hpp"

#include <cstddef>

namespace vbim::ipu {
namespace {

// A code of the standard's tables: `len` bits, value `code` (MSB first), meaning a, b.
struct Code {
  std::uint8_t len;
  std::uint16_t code;
  std::int16_t a;
  std::int16_t b;
};

// Table B.1 macroblock_address_increment.
constexpr Code kB1[] = {
    {1, 0x1, 1, 0},
    {3, 0x3, 2, 0},
    {3, 0x2, 3, 0},
    {4, 0x3, 4, 0},
    {4, 0x2, 5, 0},
    {5, 0x3, 6, 0},
    {5, 0x2, 7, 0},
    {7, 0x7, 8, 0},
    {7, 0x6, 9, 0},
    {8, 0xB, 10, 0},
    {8, 0xA, 11, 0},
    {8, 0x9, 12, 0},
    {8, 0x8, 13, 0},
    {8, 0x7, 14, 0},
    {8, 0x6, 15, 0},
    {10, 0x17, 16, 0},
    {10, 0x16, 17, 0},
    {10, 0x15, 18, 0},
    {10, 0x14, 19, 0},
    {10, 0x13, 20, 0},
    {10, 0x12, 21, 0},
    {11, 0x23, 22, 0},
    {11, 0x22, 23, 0},
    {11, 0x21, 24, 0},
    {11, 0x20, 25, 0},
    {11, 0x1F, 26, 0},
    {11, 0x1E, 27, 0},
    {11, 0x1D, 28, 0},
    {11, 0x1C, 29, 0},
    {11, 0x1B, 30, 0},
    {11, 0x1A, 31, 0},
    {11, 0x19, 32, 0},
    {11, 0x18, 33, 0},
    {11, 0x08, kMbaEscape, 0},
    {11, 0x0F, kMbaStuffing, 0},
};

// Table B.2 macroblock_type in I pictures: '1' intra, '01' intra + quant (value 1).
constexpr Code kB2[] = {{1, 0x1, 0, 0}, {2, 0x1, 1, 0}};

// Table B.10 motion_code, positive values; the last bit is the sign (1 = negative) except for 0.
constexpr Code kB10[] = {
    {1, 0x1, 0, 0},    {3, 0x2, 1, 0},    {4, 0x2, 2, 0},    {5, 0x2, 3, 0},    {7, 0x6, 4, 0},    {8, 0xA, 5, 0},
    {8, 0x8, 6, 0},    {8, 0x6, 7, 0},    {10, 0x16, 8, 0},  {10, 0x14, 9, 0},  {10, 0x12, 10, 0}, {11, 0x22, 11, 0},
    {11, 0x20, 12, 0}, {11, 0x1E, 13, 0}, {11, 0x1C, 14, 0}, {11, 0x1A, 15, 0}, {11, 0x18, 16, 0},
};

// Table B.12 dct_dc_size_luminance and B.13 dct_dc_size_chrominance.
constexpr Code kB12[] = {{3, 0x4, 0, 0},  {2, 0x0, 1, 0},  {2, 0x1, 2, 0},    {3, 0x5, 3, 0},
                         {3, 0x6, 4, 0},  {4, 0xE, 5, 0},  {5, 0x1E, 6, 0},   {6, 0x3E, 7, 0},
                         {7, 0x7E, 8, 0}, {8, 0xFE, 9, 0}, {9, 0x1FE, 10, 0}, {9, 0x1FF, 11, 0}};
constexpr Code kB13[] = {{2, 0x0, 0, 0},  {2, 0x1, 1, 0},   {2, 0x2, 2, 0},     {3, 0x6, 3, 0},
                         {4, 0xE, 4, 0},  {5, 0x1E, 5, 0},  {6, 0x3E, 6, 0},    {7, 0x7E, 7, 0},
                         {8, 0xFE, 8, 0}, {9, 0x1FE, 9, 0}, {10, 0x3FE, 10, 0}, {10, 0x3FF, 11, 0}};

// Codes of length 12..16 (all starting '0000 000') shared by B.14 and B.15: run, level.
#define VBIM_DCT_LONG_CODES                                                                                            \
  {12, 0x10, 0, 11}, {12, 0x11, 8, 2}, {12, 0x12, 4, 3}, {12, 0x13, 0, 10}, {12, 0x14, 2, 4}, {12, 0x15, 7, 2},        \
      {12, 0x16, 21, 1}, {12, 0x17, 20, 1}, {12, 0x18, 0, 9}, {12, 0x19, 19, 1}, {12, 0x1A, 18, 1}, {12, 0x1B, 1, 5},  \
      {12, 0x1C, 3, 3}, {12, 0x1D, 0, 8}, {12, 0x1E, 6, 2}, {12, 0x1F, 17, 1}, {13, 0x10, 10, 2}, {13, 0x11, 9, 2},    \
      {13, 0x12, 5, 3}, {13, 0x13, 3, 4}, {13, 0x14, 2, 5}, {13, 0x15, 1, 7}, {13, 0x16, 1, 6}, {13, 0x17, 0, 15},     \
      {13, 0x18, 0, 14}, {13, 0x19, 0, 13}, {13, 0x1A, 0, 12}, {13, 0x1B, 26, 1}, {13, 0x1C, 25, 1},                   \
      {13, 0x1D, 24, 1}, {13, 0x1E, 23, 1}, {13, 0x1F, 22, 1}, {14, 0x10, 0, 31}, {14, 0x11, 0, 30},                   \
      {14, 0x12, 0, 29}, {14, 0x13, 0, 28}, {14, 0x14, 0, 27}, {14, 0x15, 0, 26}, {14, 0x16, 0, 25},                   \
      {14, 0x17, 0, 24}, {14, 0x18, 0, 23}, {14, 0x19, 0, 22}, {14, 0x1A, 0, 21}, {14, 0x1B, 0, 20},                   \
      {14, 0x1C, 0, 19}, {14, 0x1D, 0, 18}, {14, 0x1E, 0, 17}, {14, 0x1F, 0, 16}, {15, 0x10, 0, 40},                   \
      {15, 0x11, 0, 39}, {15, 0x12, 0, 38}, {15, 0x13, 0, 37}, {15, 0x14, 0, 36}, {15, 0x15, 0, 35},                   \
      {15, 0x16, 0, 34}, {15, 0x17, 0, 33}, {15, 0x18, 0, 32}, {15, 0x19, 1, 14}, {15, 0x1A, 1, 13},                   \
      {15, 0x1B, 1, 12}, {15, 0x1C, 1, 11}, {15, 0x1D, 1, 10}, {15, 0x1E, 1, 9}, {15, 0x1F, 1, 8}, {16, 0x10, 1, 18},  \
      {16, 0x11, 1, 17}, {16, 0x12, 1, 16}, {16, 0x13, 1, 15}, {16, 0x14, 6, 3}, {16, 0x15, 16, 2}, {16, 0x16, 15, 2}, \
      {16, 0x17, 14, 2}, {16, 0x18, 13, 2}, {16, 0x19, 12, 2}, {16, 0x1A, 11, 2}, {16, 0x1B, 31, 1},                   \
      {16, 0x1C, 30, 1}, {16, 0x1D, 29, 1}, {16, 0x1E, 28, 1}, {                                                       \
    16, 0x1F, 27, 1                                                                                                    \
  }

// Table B.14 (DCT coefficients table zero) as used for intra AC coefficients ('11s' for run 0,
// level 1; the '1s' form applies only to the first coefficient of non-intra blocks).
constexpr Code kB14[] = {
    {2, 0x2, 0, kDctEob},    {2, 0x3, 0, 1},   {3, 0x3, 1, 1},   {4, 0x4, 0, 2},      {4, 0x5, 2, 1},  {5, 0x5, 0, 3},
    {5, 0x6, 4, 1},          {5, 0x7, 3, 1},   {6, 0x4, 7, 1},   {6, 0x5, 6, 1},      {6, 0x6, 1, 2},  {6, 0x7, 5, 1},
    {6, 0x1, 0, kDctEscape}, {7, 0x4, 2, 2},   {7, 0x5, 9, 1},   {7, 0x6, 0, 4},      {7, 0x7, 8, 1},  {8, 0x20, 13, 1},
    {8, 0x21, 0, 6},         {8, 0x22, 12, 1}, {8, 0x23, 11, 1}, {8, 0x24, 3, 2},     {8, 0x25, 1, 3}, {8, 0x26, 0, 5},
    {8, 0x27, 10, 1},        {10, 0x8, 16, 1}, {10, 0x9, 5, 2},  {10, 0xA, 0, 7},     {10, 0xB, 2, 3}, {10, 0xC, 1, 4},
    {10, 0xD, 15, 1},        {10, 0xE, 14, 1}, {10, 0xF, 4, 2},  VBIM_DCT_LONG_CODES,
};

// Table B.15 (DCT coefficients table one), intra_vlc_format = 1.
constexpr Code kB15[] = {
    {2, 0x2, 0, 1},   {3, 0x2, 1, 1},   {3, 0x6, 0, 2},   {4, 0x6, 0, kDctEob}, {4, 0x7, 0, 3},
    {5, 0x5, 2, 1},   {5, 0x6, 1, 2},   {5, 0x7, 3, 1},   {5, 0x1C, 0, 4},      {5, 0x1D, 0, 5},
    {6, 0x4, 0, 7},   {6, 0x5, 0, 6},   {6, 0x6, 4, 1},   {6, 0x7, 5, 1},       {6, 0x1, 0, kDctEscape},
    {7, 0x4, 7, 1},   {7, 0x5, 8, 1},   {7, 0x6, 6, 1},   {7, 0x7, 2, 2},       {7, 0x78, 9, 1},
    {7, 0x79, 1, 3},  {7, 0x7A, 10, 1}, {7, 0x7B, 0, 8},  {7, 0x7C, 0, 9},      {8, 0x20, 1, 5},
    {8, 0x21, 11, 1}, {8, 0x22, 0, 11}, {8, 0x23, 0, 10}, {8, 0x24, 13, 1},     {8, 0x25, 12, 1},
    {8, 0x26, 3, 2},  {8, 0x27, 1, 4},  {8, 0xFA, 0, 12}, {8, 0xFB, 0, 13},     {8, 0xFC, 2, 3},
    {8, 0xFD, 4, 2},  {8, 0xFE, 0, 14}, {8, 0xFF, 0, 15}, {9, 0x4, 5, 2},       {9, 0x5, 14, 1},
    {9, 0x7, 15, 1},  {10, 0xC, 2, 4},  {10, 0xD, 16, 1}, VBIM_DCT_LONG_CODES,
};
#undef VBIM_DCT_LONG_CODES

// Fills a direct table of 2^bits entries: every index whose top `len` bits equal the code.
template <std::size_t N, std::size_t M>
void fillDirect(VlcEntry (&table)[N], int bits, const Code (&codes)[M]) {
  for (auto& e : table) e = VlcEntry{0, 0};
  for (const Code& c : codes) {
    const int free = bits - c.len;
    const std::size_t first = static_cast<std::size_t>(c.code) << free;
    for (std::size_t i = 0; i < (std::size_t{1} << free); ++i) {
      table[first + i] = VlcEntry{static_cast<std::int8_t>(c.a), c.len};
    }
  }
}

// B.10: the codes above end in the sign bit (0 = positive); the negative code has it set.
void fillMotion(VlcEntry (&table)[1 << 11]) {
  for (auto& e : table) e = VlcEntry{0, 0};
  for (const Code& c : kB10) {
    for (int s = 0; s < (c.a == 0 ? 1 : 2); ++s) {
      const std::uint32_t code = static_cast<std::uint32_t>(c.code) | static_cast<std::uint32_t>(s);
      const int free = 11 - c.len;
      for (std::uint32_t i = 0; i < (1u << free); ++i) {
        table[(code << free) + i] = VlcEntry{static_cast<std::int8_t>(s ? -c.a : c.a), c.len};
      }
    }
  }
}

// Fills a direct table indexed by the next `bits` bits with the run/level codes of minLen..maxLen
// bits, once per sign bit (index = code, sign, then don't-care bits).
template <std::size_t N, std::size_t M>
void fillDctCodes(DctCodeEntry (&table)[N], int bits, int minLen, int maxLen, const Code (&codes)[M]) {
  for (const Code& c : codes) {
    if (c.b <= 0 || c.len < minLen || c.len > maxLen) continue;
    for (int s = 0; s < 2; ++s) {
      const std::uint32_t code = (static_cast<std::uint32_t>(c.code) << 1) | static_cast<std::uint32_t>(s);
      const int free = bits - (c.len + 1);
      for (std::uint32_t i = 0; i < (1u << free); ++i) {
        table[(code << free) + i] =
            DctCodeEntry{static_cast<std::uint8_t>(c.len + 1), static_cast<std::uint8_t>(c.a + 1),
                         static_cast<std::uint8_t>(c.b), static_cast<std::uint8_t>(s)};
      }
    }
  }
}

// The short table: run/level codes of up to kDctShortBits - 1 bits once per sign; EOB, escape
// and the prefixes of the long codes marked by kind.
template <std::size_t M>
void fillDctShort(DctCodeEntry (&table)[1 << VlcTables::kDctShortBits], const Code (&codes)[M]) {
  constexpr int kBits = VlcTables::kDctShortBits;
  for (auto& e : table) e = DctCodeEntry{0, kDctKindInvalid, 0, 0};
  fillDctCodes(table, kBits, 1, kBits - 1, codes);
  for (const Code& c : codes) {
    if (c.b != kDctEob && c.b != kDctEscape) continue;
    const int free = kBits - c.len;
    const std::uint8_t kind = c.b == kDctEob ? kDctKindEob : kDctKindEscape;
    for (int i = 0; i < (1 << free); ++i) table[(c.code << free) + i] = DctCodeEntry{c.len, kind, 0, 0};
  }
  // Every code longer than kBits - 1 bits begins with seven zeros: indices below 2^(kBits - 7).
  for (int i = 0; i < (1 << (kBits - 7)); ++i) {
    if (table[i].bits == 0) table[i] = DctCodeEntry{0, kDctKindLong, 0, 0};
  }
}

// A non-intra table from the short table of B.14: the first symbol of each index (for the first
// code of a block, '1s' is run 0, level 1, and no EOB begins with '1'), and an EOB after it if its
// whole code lies in the index's remaining bits (the short table gives a code's meaning from its
// leading bits, the bits after it being don't-care).
void fillDctNonIntra(DctCodeEobEntry (&table)[1 << VlcTables::kDctShortBits],
                     const DctCodeEntry (&codes)[1 << VlcTables::kDctShortBits], bool firstOfBlock) {
  constexpr int kBits = VlcTables::kDctShortBits;
  constexpr std::uint32_t kAll = (1u << kBits) - 1;
  for (std::uint32_t index = 0; index <= kAll; ++index) {
    DctCodeEntry code = codes[index];
    if (firstOfBlock && (index >> (kBits - 1)) != 0) {
      code = DctCodeEntry{2, 1, 1, static_cast<std::uint8_t>((index >> (kBits - 2)) & 1)};
    }
    DctCodeEobEntry& e = table[index];
    e = DctCodeEobEntry{0, 0, 0, 0};
    if (code.level == 0) {
      if (code.step == kDctKindEob) e = DctCodeEobEntry{code.bits, 0, 0, 1};
      continue;
    }
    const int level = 2 * code.level + 1;
    e = DctCodeEobEntry{code.bits, code.step, static_cast<std::int8_t>(code.negative ? -level : level), 0};
    const DctCodeEntry next = codes[(index << code.bits) & kAll];
    if (next.level == 0 && next.step == kDctKindEob && code.bits + next.bits <= kBits) {
      e.bits = static_cast<std::uint8_t>(code.bits + next.bits);
      e.eob = 1;
    }
  }
}

// The pair table of an intra table from its short table: the symbol each index begins with, the
// next one too when it is also a run/level code whose whole code lies in the index's remaining bits,
// and an end of block after the last of them when that fits as well (a code's meaning is given by
// its leading bits, the index's bits after it being don't-care, so a code that fits is read right).
void fillDctPairs(DctPairEntry (&table)[1 << VlcTables::kDctPairBits],
                  const DctCodeEntry (&codes)[1 << VlcTables::kDctShortBits]) {
  constexpr int kBits = VlcTables::kDctPairBits;
  constexpr int kDrop = kBits - VlcTables::kDctShortBits;  // the short table reads fewer bits
  static_assert(kDrop >= 0);
  constexpr std::uint32_t kAll = (1u << kBits) - 1;
  // The symbol at bit `used` of index, if its whole code lies in the index.
  auto next = [&](std::uint32_t index, int used) {
    const DctCodeEntry c = codes[((index << used) & kAll) >> kDrop];
    return c.bits != 0 && used + c.bits <= kBits ? c : DctCodeEntry{0, kDctKindInvalid, 0, 0};
  };
  auto isEob = [](const DctCodeEntry& c) { return c.level == 0 && c.step == kDctKindEob && c.bits != 0; };
  for (std::uint32_t index = 0; index <= kAll; ++index) {
    DctPairEntry& e = table[index];
    e = DctPairEntry{0, 0, 0, 0, 0, 0, 0, 0};
    const DctCodeEntry first = codes[index >> kDrop];
    if (first.level == 0) continue;
    e.bits = first.bits;
    e.step1 = first.step;
    e.level1 = first.level;
    e.negative1 = first.negative;
    DctCodeEntry after = next(index, e.bits);
    if (after.level != 0) {
      e.bits = static_cast<std::uint8_t>(e.bits + after.bits);
      e.step2 = after.step;
      e.level2 = after.level;
      e.negative2 = after.negative;
      after = next(index, e.bits);
    }
    if (isEob(after)) {
      e.bits = static_cast<std::uint8_t>(e.bits + after.bits);
      e.eob = 1;
    }
  }
}

VlcTables build() {
  VlcTables t{};
  fillDirect(t.mbAddressIncrement, 11, kB1);
  fillDirect(t.intraMbType, 2, kB2);
  fillMotion(t.motionCode);
  fillDirect(t.dcSizeLuma, 9, kB12);
  fillDirect(t.dcSizeChroma, 10, kB13);
  fillDctShort(t.dctShort[0], kB14);
  fillDctShort(t.dctShort[1], kB15);
  // The long codes are the same in both tables.
  for (auto& e : t.dctLong) e = DctCodeEntry{0, kDctKindInvalid, 0, 0};
  fillDctCodes(t.dctLong, VlcTables::kDctLongBits, VlcTables::kDctShortBits, 16, kB14);
  fillDctPairs(t.dctPairs[0], t.dctShort[0]);
  fillDctPairs(t.dctPairs[1], t.dctShort[1]);
  fillDctNonIntra(t.dctNonIntra[0], t.dctShort[0], true);
  fillDctNonIntra(t.dctNonIntra[1], t.dctShort[0], false);
  return t;
}

}  // namespace

const VlcTables& vlcTables() {
  static const VlcTables tables = build();
  return tables;
}

}  // namespace vbim::ipu
