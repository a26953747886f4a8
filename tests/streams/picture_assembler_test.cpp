#include <gtest/gtest.h>

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
