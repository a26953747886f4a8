// The non-intra DCT coefficient tables (VlcTables::dctNonIntra): every index against the short table
// of B.14 it is built from and the rules of §7.2.2.1 (the '1s' form of a block's first code, the
// end of block '10' read with the code before it when it fits), plus known answers from Table B.14.
// The intra pair tables (VlcTables::dctPairs): every index against reading its bits a code at a
// time from the short table, plus known answers from Tables B.14 and B.15.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {
namespace {

constexpr int kBits = VlcTables::kDctShortBits;
constexpr std::uint32_t kAll = (1u << kBits) - 1;

// The entry for the bits `code` (MSB first, `len` bits) followed by zeros.
DctCodeEobEntry at(int table, std::uint32_t code, int len) {
  return vlcTables().dctNonIntra[table][code << (kBits - len)];
}

TEST(VlcTables, NonIntraKnownAnswers) {
  // Table B.14: '1s' is run 0, level 1 only as a block's first code; after it '11s' is, and
  // '10' is the end of block.
  DctCodeEobEntry e = at(0, 0b10, 2);  // '1' '0' (positive), then zeros: no EOB follows
  EXPECT_EQ(e.bits, 2);
  EXPECT_EQ(e.step, 1);
  EXPECT_EQ(e.level, 3);
  EXPECT_EQ(e.eob, 0);
  e = at(0, 0b11'10, 4);  // '1s' negative, then an EOB
  EXPECT_EQ(e.bits, 4);
  EXPECT_EQ(e.level, -3);
  EXPECT_EQ(e.eob, 1);
  e = at(1, 0b10, 2);  // EOB alone
  EXPECT_EQ(e.bits, 2);
  EXPECT_EQ(e.level, 0);
  EXPECT_EQ(e.eob, 1);
  e = at(1, 0b110'10, 5);  // '11s' run 0 level 1, then EOB
  EXPECT_EQ(e.bits, 5);
  EXPECT_EQ(e.step, 1);
  EXPECT_EQ(e.level, 3);
  EXPECT_EQ(e.eob, 1);
  e = at(1, 0b0100'1, 5);  // '0100s' run 0 level 2, negative
  EXPECT_EQ(e.bits, 5);
  EXPECT_EQ(e.step, 1);
  EXPECT_EQ(e.level, -5);
  EXPECT_EQ(e.eob, 0);
  e = at(0, 0b0111'10, 6);  // '011s' run 1 level 1 as a first code, then EOB
  EXPECT_EQ(e.bits, 6);
  EXPECT_EQ(e.step, 2);
  EXPECT_EQ(e.level, -3);
  EXPECT_EQ(e.eob, 1);
  e = at(1, 0b0000'0010'010, 11);  // '0000 0010 01s' run 5 level 2: no room for an EOB
  EXPECT_EQ(e.bits, 11);
  EXPECT_EQ(e.step, 6);
  EXPECT_EQ(e.level, 5);
  EXPECT_EQ(e.eob, 0);
  EXPECT_EQ(at(1, 0b0000'01, 6).level, 0);  // escape: looked up in the short table
  EXPECT_EQ(at(1, 0b0000'01, 6).eob, 0);
  EXPECT_EQ(at(0, 0, 1).level, 0);  // a long code's prefix
}

TEST(VlcTables, NonIntraEveryIndexMatchesTheShortTable) {
  const VlcTables& t = vlcTables();
  for (int table = 0; table < 2; ++table) {
    for (std::uint32_t index = 0; index <= kAll; ++index) {
      SCOPED_TRACE("table " + std::to_string(table) + ", index " + std::to_string(index));
      const DctCodeEobEntry e = t.dctNonIntra[table][index];
      DctCodeEntry code = t.dctShort[0][index];
      if (table == 0 && (index >> (kBits - 1)) != 0) {
        code = DctCodeEntry{2, 1, 1, static_cast<std::uint8_t>((index >> (kBits - 2)) & 1)};
      }
      if (code.level == 0) {
        // EOB alone (never first in a block), or a symbol for the slow path.
        const bool eob = code.step == kDctKindEob;
        EXPECT_EQ(e.level, 0);
        EXPECT_EQ(e.eob, eob ? 1 : 0);
        if (eob) {
          EXPECT_EQ(e.bits, 2);
          EXPECT_NE(table, 0);
        }
        continue;
      }
      const int level = 2 * code.level + 1;
      EXPECT_EQ(e.level, code.negative ? -level : level);
      EXPECT_EQ(e.step, code.step);
      // The EOB '10' right after the code, inside the index.
      const bool eobFits = code.bits + 2 <= kBits && ((index >> (kBits - code.bits - 2)) & 3) == 2;
      EXPECT_EQ(e.eob, eobFits ? 1 : 0);
      EXPECT_EQ(e.bits, code.bits + (eobFits ? 2 : 0));
    }
  }
}

// The pair entry for the bits `code` (MSB first, `len` bits) followed by zeros.
DctPairEntry pairAt(int table, std::uint32_t code, int len) {
  return vlcTables().dctPairs[table][code << (VlcTables::kDctPairBits - len)];
}

// An entry as text, so that a whole entry is compared at once and a difference reads plainly.
std::string show(const DctPairEntry& e) {
  return "bits " + std::to_string(e.bits) + ", (step " + std::to_string(e.step1) + ", level " +
         std::to_string(e.level1) + ", negative " + std::to_string(e.negative1) + "), (step " +
         std::to_string(e.step2) + ", level " + std::to_string(e.level2) + ", negative " + std::to_string(e.negative2) +
         "), eob " + std::to_string(e.eob);
}

TEST(VlcTables, IntraPairKnownAnswers) {
  // Fields: bits, step1, level1, negative1, step2, level2, negative2, eob (step = run + 1).
  // B.14: '11s' run 0 level 1, '011s' run 1 level 1 negative, '10' end of block.
  EXPECT_EQ(show(pairAt(0, 0b110'0111'10, 9)), show({9, 1, 1, 0, 2, 1, 1, 1}));
  // B.14: '0010 0110s' run 0 level 5 (9 bits with its sign), then '11s' needs 3 more: one code only.
  EXPECT_EQ(show(pairAt(0, 0b0010'0110'1'11, 11)), show({9, 1, 5, 1, 0, 0, 0, 0}));
  // B.15: '10s' run 0 level 1, '110s' run 0 level 2 negative, then '0110' end of block: 11 bits.
  EXPECT_EQ(show(pairAt(1, 0b100'1101'0110, 11)), show({11, 1, 1, 0, 1, 2, 1, 1}));
  // B.15: '10s' negative, then the end of block.
  EXPECT_EQ(show(pairAt(1, 0b101'0110, 7)), show({7, 1, 1, 1, 0, 0, 0, 1}));
  // Not a run/level code first (an end of block, an escape, a long code's prefix): all zero, the
  // decoder looks the symbol up in the short table.
  const std::string none = show({0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(show(pairAt(0, 0b10, 2)), none);
  EXPECT_EQ(show(pairAt(1, 0b0110, 4)), none);
  EXPECT_EQ(show(pairAt(0, 0b0000'01, 6)), none);
  EXPECT_EQ(show(pairAt(1, 0, 1)), none);
}

TEST(VlcTables, IntraPairsEveryIndexMatchesReadingCodeByCode) {
  const VlcTables& t = vlcTables();
  constexpr int kPairBits = VlcTables::kDctPairBits;
  for (int table = 0; table < 2; ++table) {
    for (std::uint32_t index = 0; index < (1u << kPairBits); ++index) {
      SCOPED_TRACE("table " + std::to_string(table) + ", index " + std::to_string(index));
      // The next symbol at bit `used` of the index: its entry in the short table, or nothing if its
      // code does not lie within the index.
      auto symbol = [&](int used, DctCodeEntry& c) {
        // The short table's index: the 11 bits from `used`, zeros past the end of the index.
        const std::uint64_t bits = static_cast<std::uint64_t>(index) << (64 - kPairBits);
        c = t.dctShort[table][static_cast<std::uint32_t>((bits << used) >> (64 - kBits))];
        return c.bits != 0 && used + c.bits <= kPairBits;
      };
      const DctPairEntry e = t.dctPairs[table][index];
      DctCodeEntry c{};
      if (!symbol(0, c) || c.level == 0) {
        EXPECT_EQ(show(e), show({0, 0, 0, 0, 0, 0, 0, 0}));
        continue;
      }
      int used = c.bits;
      EXPECT_EQ(e.step1, c.step);
      EXPECT_EQ(e.level1, c.level);
      EXPECT_EQ(e.negative1, c.negative);
      DctCodeEntry d{};
      const bool second = symbol(used, d) && d.level != 0;
      if (second) {
        used += d.bits;
        EXPECT_EQ(e.step2, d.step);
        EXPECT_EQ(e.level2, d.level);
        EXPECT_EQ(e.negative2, d.negative);
      } else {
        EXPECT_EQ(e.step2, 0);
        EXPECT_EQ(e.level2, 0);
      }
      DctCodeEntry end{};
      const bool eob = symbol(used, end) && end.level == 0 && end.step == kDctKindEob;
      EXPECT_EQ(e.eob, eob ? 1 : 0);
      EXPECT_EQ(e.bits, used + (eob ? end.bits : 0));
    }
  }
}

}  // namespace
}  // namespace vbim::ipu
