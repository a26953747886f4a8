// ee::DecodeOrder against the coded order MPEG-2 prescribes (ISO/IEC 13818-2 §6.1.1.11: each I or P
// picture moves ahead of the B pictures shown before it), written out by hand for closed and open
// GOPs, and the run rule a branch relies on.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ee/decode_order.hpp"

namespace vbim::ee {
namespace {

using streams::PictureType;

// One stream, one or more variants of the same pattern ("IBBP..."; 'i' = an I picture that opens an
// open GOP), pictures laid out in the file in coded order.
streams::Descriptor describe(const std::string& pattern, int variants = 1) {
  streams::Descriptor d;
  d.framesPerVariant = static_cast<std::uint32_t>(pattern.size());
  for (int v = 0; v < variants; ++v) d.variants.push_back(streams::Variant{"v" + std::to_string(v)});
  d.streams.push_back(streams::StreamEntry{});
  std::vector<streams::IndexEntry> index;
  for (int v = 0; v < variants; ++v) {
    for (const char c : pattern) {
      streams::IndexEntry e;
      e.type = c == 'B' ? PictureType::B : c == 'P' ? PictureType::P : PictureType::I;
      e.gopStart = c == 'I' || c == 'i';
      e.closedGop = c == 'I';
      index.push_back(e);
    }
  }
  // Coded order: a reference, then the B pictures shown before it (since the previous reference).
  std::vector<std::size_t> coded;
  const std::size_t n = pattern.size();
  for (int v = 0; v < variants; ++v) {
    std::vector<std::size_t> pendingB;
    for (std::size_t f = 0; f < n; ++f) {
      const std::size_t g = static_cast<std::size_t>(v) * n + f;
      if (index[g].type == PictureType::B) {
        pendingB.push_back(g);
      } else {
        coded.push_back(g);
        coded.insert(coded.end(), pendingB.begin(), pendingB.end());
        pendingB.clear();
      }
    }
  }
  for (std::size_t i = 0; i < coded.size(); ++i) index[coded[i]].sector = static_cast<std::uint32_t>(10 + i);
  d.index.push_back(index);
  return d;
}

// Frames of variant 0 in decode order for a run from `start` (by rank).
std::vector<std::int64_t> decodeOrder(const DecodeOrder& o, std::int64_t start, std::int64_t frames) {
  std::vector<std::int64_t> out;
  for (std::int64_t r = start; r < frames; ++r) out.push_back(o.frameAtRank(0, r, start));
  return out;
}

TEST(DecodeOrder, IntraOnlyStreamsDecodeInDisplayOrder) {
  const DecodeOrder o(describe("IIIIII"), 0);
  EXPECT_TRUE(o.intraOnly());
  EXPECT_EQ(decodeOrder(o, 0, 6), (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
  for (std::int64_t f = 0; f < 6; ++f) EXPECT_EQ(o.rank(0, f, 0), f);
}

TEST(DecodeOrder, ClosedGopsMoveEachReferenceAheadOfItsBPictures) {
  const DecodeOrder o(describe("IBBPBBPBBIBP"), 0);
  EXPECT_FALSE(o.intraOnly());
  EXPECT_EQ(decodeOrder(o, 0, 12), (std::vector<std::int64_t>{0, 3, 1, 2, 6, 4, 5, 9, 7, 8, 11, 10}));
  // rank and frameAtRank are inverses; the file's order is the decode order.
  for (std::int64_t f = 0; f < 12; ++f) EXPECT_EQ(o.frameAtRank(0, o.rank(0, f, 0), 0), f);
  const std::vector<std::int64_t> order = decodeOrder(o, 0, 12);
  for (std::size_t i = 0; i + 1 < order.size(); ++i) EXPECT_EQ(o.nextInFile(order[i]), order[i + 1]);
  EXPECT_EQ(o.nextInFile(10), -1);
}

// Open GOP: the I at 9 is decoded before B 7 and 8, which refer back to P 6. A run that starts at
// that I (a branch) decodes from it and never needs 7 or 8; one that starts at 0 decodes all.
TEST(DecodeOrder, ARunFromAnOpenGopsIStartsThere) {
  const DecodeOrder o(describe("IBBPBBPBBiBP"), 0);
  EXPECT_EQ(o.resumeFrame(0, 8), 0);
  EXPECT_EQ(o.resumeFrame(0, 10), 9);
  EXPECT_EQ(decodeOrder(o, 0, 12), (std::vector<std::int64_t>{0, 3, 1, 2, 6, 4, 5, 9, 7, 8, 11, 10}));
  EXPECT_EQ(decodeOrder(o, 9, 12), (std::vector<std::int64_t>{9, 11, 10}));
  EXPECT_EQ(o.rank(0, 9, 9), 9);
  EXPECT_EQ(o.rank(0, 11, 9), 10);
  EXPECT_EQ(o.rank(0, 10, 9), 11);
}

TEST(DecodeOrder, EachVariantHasItsOwnRanks) {
  const DecodeOrder o(describe("IBBPBP", 2), 0);
  EXPECT_EQ(o.type(6), PictureType::I);
  EXPECT_EQ(o.frameAtRank(1, 1, 0), 3);
  EXPECT_EQ(o.rank(1, 4, 0), 5);
  EXPECT_EQ(o.nextInFile(4), 6);  // variant 0's last picture (B 4, after P 5) then variant 1's I
}

}  // namespace
}  // namespace vbim::ee
