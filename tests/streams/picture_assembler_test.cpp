#include <gtest/gtest.h>

#include "runtime/rng.hpp"
#include "streams/picture_assembler.hpp"

namespace vbim::streams {
namespace {

// An elementary stream of `n` fake intra pictures: sequence header, GOP, picture header, one slice.
std::vector<std::uint8_t> fakeStream(int n, std::vector<std::size_t>* starts = nullptr) {
  std::vector<std::uint8_t> es;
  for (int i = 0; i < n; ++i) {
    if (starts) starts->push_back(es.size());
    for (std::uint8_t code : {0xB3, 0xB8, 0x00, 0x01}) {
      es.insert(es.end(), {0, 0, 1, code});
      for (int k = 0; k < 5 + i; ++k) es.push_back(static_cast<std::uint8_t>(0x80 + i));
    }
  }
  return es;
}

TEST(StreamsPictureAssembler, SplitsAtSequenceHeadersAcrossAnyPayloadBoundary) {
  std::vector<std::size_t> starts;
  const auto es = fakeStream(4, &starts);
  for (std::size_t chunk : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7}, es.size()}) {
    PictureAssembler a(0xE0);
    std::vector<Picture> out;
    for (std::size_t pos = 0; pos < es.size(); pos += chunk) {
      const std::size_t n = std::min(chunk, es.size() - pos);
      a.append(std::span(es).subspan(pos, n), static_cast<std::uint32_t>(pos / 16), 1000 + pos,
               std::optional<std::int64_t>(pos), out);
    }
    a.finish(out);
    ASSERT_EQ(out.size(), 4u) << "chunk " << chunk;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::size_t end = i + 1 < 4 ? starts[i + 1] : es.size();
      EXPECT_EQ(out[i].data, std::vector<std::uint8_t>(es.begin() + starts[i], es.begin() + end));
      EXPECT_EQ(out[i].byteOffset, 1000 + starts[i]) << "chunk " << chunk;
      EXPECT_EQ(out[i].firstSector, starts[i] / chunk * chunk / 16);
    }
    if (chunk == es.size()) {
      // One payload: its PTS goes to the first picture only.
      EXPECT_TRUE(out[0].pts);
      EXPECT_FALSE(out[1].pts);
    }
  }
}

// Coded bytes full of 0x00 and 0x01 (the bytes the start-code scan must look at), zero stuffing
// before start codes, and payloads of every size: each picture comes out whole, starting at its
// sequence header's 00 00 01.
TEST(StreamsPictureAssembler, FindsEveryPictureInZeroHeavyDataAtAnySplit) {
  Rng rng(23);
  for (int round = 0; round < 40; ++round) {
    std::vector<std::uint8_t> es;
    std::vector<std::size_t> starts;
    auto filler = [&](std::size_t n) {
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint8_t pick[] = {0, 0, 1, 2, 3, 0x80, 0xFF};
        std::uint8_t b = pick[rng.below(sizeof pick)];
        // No 00 00 01 inside coded data: a 1 after two zeros becomes 2.
        if (b == 1 && es.size() >= 2 && es[es.size() - 1] == 0 && es[es.size() - 2] == 0) b = 2;
        es.push_back(b);
      }
      // Nor a zero pair just before the next start code's own zeros would shift it: end on nonzero.
      es.push_back(0x80);
    };
    auto startCode = [&](std::uint8_t code) {
      const std::size_t stuffing = rng.below(4);  // extra zeros: they end the previous picture
      es.insert(es.end(), stuffing, 0);
      const std::size_t at = es.size();
      es.insert(es.end(), {0, 0, 1, code});
      return at;
    };
    const int pictures = 1 + static_cast<int>(rng.below(6));
    for (int i = 0; i < pictures; ++i) {
      starts.push_back(startCode(0xB3));
      filler(rng.below(40));
      startCode(0x00);
      filler(rng.below(40));
      for (std::uint64_t sl = 0, n = 1 + rng.below(3); sl < n; ++sl) {
        startCode(static_cast<std::uint8_t>(1 + sl));
        filler(rng.below(200));
      }
    }
    PictureAssembler a(0xE0);
    std::vector<Picture> out;
    for (std::size_t pos = 0; pos < es.size();) {
      const std::size_t n = std::min<std::size_t>(1 + rng.below(round % 2 == 0 ? 5 : 300), es.size() - pos);
      a.append(std::span(es).subspan(pos, n), 0, pos, std::nullopt, out);
      pos += n;
    }
    a.finish(out);
    ASSERT_EQ(out.size(), starts.size()) << "round " << round;
    for (std::size_t i = 0; i < starts.size(); ++i) {
      const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : es.size();
      ASSERT_EQ(out[i].byteOffset, starts[i]) << "round " << round << " picture " << i;
      ASSERT_EQ(out[i].data, std::vector<std::uint8_t>(es.begin() + static_cast<std::ptrdiff_t>(starts[i]),
                                                       es.begin() + static_cast<std::ptrdiff_t>(end)));
    }
  }
}

TEST(StreamsPictureAssembler, DiscardsBytesBeforeTheFirstHeaderAndDropsOnReset) {
  std::vector<std::size_t> starts;
  const auto es = fakeStream(3, &starts);
  PictureAssembler a(0xE1);
  std::vector<Picture> out;
  // Start in the middle of picture 0 (as after a seek).
  a.append(std::span(es).subspan(starts[0] + 33), 0, 0, std::nullopt, out);  // inside its slice
  a.finish(out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].data.front(), 0x00);
  EXPECT_EQ(out[0].data[3], 0xB3);
  EXPECT_GT(a.discardedBytes(), 0u);

  PictureAssembler b(0xE0);
  out.clear();
  b.append(std::span(es).first(starts[1] + 12), 0, 0, std::nullopt, out);
  EXPECT_EQ(out.size(), 1u);
  EXPECT_TRUE(b.reset());  // picture 1 was under way
  b.append(std::span(es).subspan(starts[1] + 12), 0, 0, std::nullopt, out);
  b.finish(out);
  EXPECT_EQ(out.size(), 2u);  // picture 1 lost, picture 2 complete
}

TEST(StreamsPictureAssembler, SequenceEndCodeCompletesThePicture) {
  auto es = fakeStream(1);
  es.insert(es.end(), {0, 0, 1, 0xB7});
  PictureAssembler a(0xE0);
  std::vector<Picture> out;
  a.append(es, 0, 0, std::nullopt, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].data.size(), es.size() - 4);
  a.finish(out);
  EXPECT_EQ(out.size(), 1u);
}

TEST(StreamsPictureAssembler, APictureLongerThanTheVbvIsDroppedAndMemoryStaysBounded) {
  PictureAssembler a(0xE0);
  std::vector<Picture> out;
  const std::vector<std::uint8_t> head = {0, 0, 1, 0xB3, 1, 2, 0, 0, 1, 0x00, 7};
  EXPECT_TRUE(a.append(head, 0, 0, std::nullopt, out));
  const std::vector<std::uint8_t> junk(2000, 0x55);
  bool dropped = false;
  for (int i = 0; i < 200 && !dropped; ++i) dropped = !a.append(junk, 0, 0, std::nullopt, out);
  EXPECT_TRUE(dropped);
  EXPECT_TRUE(out.empty());
  EXPECT_FALSE(a.reset());  // nothing under way any more
}

}  // namespace
}  // namespace vbim::streams
