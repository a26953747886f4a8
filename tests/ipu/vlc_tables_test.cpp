// The non-intra DCT coefficient tables (VlcTables::dctNonIntra): every index against the short table
// of B.14 it is built from and the rules of §7.2.2.1 (the '1s' form of a block's first code, the
// end of block '10' read with the code before it when it fits), plus known answers from Table B.14.
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

}  // namespace
}  // namespace vbim::ipu
