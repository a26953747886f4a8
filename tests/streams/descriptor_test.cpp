#include <gtest/gtest.h>

#include <span>
#include <vector>

#include "streams/crc32.hpp"
#include "streams/demuxer.hpp"
#include "streams/descriptor.hpp"
#include "streams/descriptor_packs.hpp"
#include "streams/format.hpp"

namespace vbim::streams {
namespace {

Descriptor sample(std::uint32_t frames = 3) {
  Descriptor d;
  d.gameFps = {30000, 1001};
  d.framesPerVariant = frames;
  d.loopFrame = 1;
  d.firstPts = 48600;
  d.ptsPerFrame = 3600;
  d.descriptorSectors = 1;
  d.totalSectors = 99;
  d.streams = {{kLightmapStream, StreamRole::Lightmap, 256, 256}, {kSkyStream, StreamRole::Sky, 128, 64}};
  d.variants = {{"clear", 0, 1}, {"overcast", frames, 40}};
  d.index.assign(2, std::vector<IndexEntry>(2 * frames));
  for (std::uint32_t s = 0; s < 2; ++s)
    for (std::uint32_t f = 0; f < 2 * frames; ++f)
      d.index[s][f] = IndexEntry{1 + 3 * f + s, static_cast<std::uint16_t>(17 * f % 2048), 1000 + f, 0xABCD0000u + f};
  return d;
}

TEST(StreamsCrc32, MatchesTheStandardCheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()}), 0xCBF43926u);
}

// The slicing-by-8 CRC against the bit-at-a-time definition, at every length and split around
// its 8-byte steps, continued across calls as the demuxer does.
TEST(StreamsCrc32, EightBytesAtATimeEqualsTheBitwiseDefinition) {
  const auto bitwise = [](const std::vector<std::uint8_t>& d) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::uint8_t b : d) {
      c ^= b;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
  };
  std::vector<std::uint8_t> data;
  std::uint32_t x = 12345;
  for (std::size_t n = 0; n <= 67; ++n) {
    const std::uint32_t want = bitwise(data);
    EXPECT_EQ(crc32(data), want) << n;
    const std::size_t cut = n / 3;
    const std::span<const std::uint8_t> all(data);
    EXPECT_EQ(crc32(all.subspan(cut), crc32(all.first(cut))), want) << n;
    x = x * 1103515245u + 12345u;
    data.push_back(static_cast<std::uint8_t>(x >> 16));
  }
}

TEST(StreamsDescriptor, SerialisesToTheDocumentedSizeAndParsesBack) {
  const Descriptor d = sample();
  const auto body = serialize(d);
  EXPECT_EQ(body.size(), 48u + 2 * 8 + 2 * 32 + 2 * 6 * 16);
  EXPECT_EQ(body.size(), serializedSize(2, 2, 3));
  // A few documented offsets (docs/stream-format.md).
  EXPECT_EQ(body[0], 0);
  EXPECT_EQ(body[1], 1);  // version 1
  EXPECT_EQ(body[4] << 24 | body[5] << 16 | body[6] << 8 | body[7], 30000);
  EXPECT_EQ(body[48], kLightmapStream);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&body[64]), 5), "clear");
  const DescriptorParse r = parseDescriptor(body);
  ASSERT_TRUE(r.descriptor) << r.error;
  EXPECT_EQ(*r.descriptor, d);
  EXPECT_EQ(r.descriptor->frameOfPts(48600 + 3600 * 4), 4u);
  EXPECT_FALSE(r.descriptor->frameOfPts(48600 + 100));
  EXPECT_EQ(r.descriptor->variantOf(4), 1u);
}

TEST(StreamsDescriptor, ABitFlipAnywhereFailsTheCrc) {
  const auto body = serialize(sample());
  for (std::size_t at : {std::size_t{5}, std::size_t{50}, body.size() - 1}) {
    auto bad = body;
    bad[at] ^= 0x10;
    const DescriptorParse r = parseDescriptor(bad);
    EXPECT_FALSE(r.descriptor) << "flip at " << at;
    EXPECT_NE(r.error.find("CRC"), std::string::npos) << r.error;
  }
}

TEST(StreamsDescriptor, RejectsTruncationAndInconsistentFields) {
  auto body = serialize(sample());
  // erase, not resize(size - 16): GCC 12 at -O1 (the sanitizer build) cannot rule out the growing
  // branch of resize here and warns of an impossible memset size (-Wstringop-overflow).
  ASSERT_GT(body.size(), 16u);
  body.erase(body.end() - 16, body.end());
  const DescriptorParse r = parseDescriptor(body);
  EXPECT_FALSE(r.descriptor);
  EXPECT_NE(r.error.find("need"), std::string::npos) << r.error;
  Descriptor d = sample();
  d.loopFrame = 3;
  EXPECT_NE(d.validate().find("loop frame"), std::string::npos);
  EXPECT_THROW(serialize(d), std::invalid_argument);
  d = sample();
  d.variants[1].name = "clear";
  EXPECT_NE(d.validate().find("used twice"), std::string::npos);
  d = sample();
  d.variants[1].name = std::string(24, 'x');
  EXPECT_FALSE(d.validate().empty());
}

TEST(StreamsDescriptorPacks, SpanSeveralWholePacksAndReassembleInTheDemuxer) {
  const Descriptor d = sample(200);  // 2 streams x 400 frames x 16 B: several packs
  const auto body = serialize(d);
  std::vector<std::uint8_t> sys = {0, 0, 1, kSystemHeaderStartCode, 0, 6, 0x80, 0, 1, 0, 0, 0xFF};
  const std::size_t k = descriptorPackCount(body.size(), sys.size());
  ASSERT_GT(k, 5u);
  std::vector<std::int64_t> scr(k, 0);
  const auto packs = makeDescriptorPacks(body, sys, 25200, scr);
  ASSERT_EQ(packs.size(), k * kSectorBytes);
  Demuxer dm;
  // Fed in reverse, the chunks still assemble (they carry their index).
  for (std::size_t i = k; i-- > 0;)
    EXPECT_EQ(dm.feed(std::span(packs).subspan(i * kSectorBytes, kSectorBytes), static_cast<std::uint32_t>(i)), 0u)
        << dm.errors().back().describe();
  ASSERT_TRUE(dm.descriptor());
  EXPECT_EQ(*dm.descriptor(), d);
  EXPECT_EQ(dm.stats().systemHeaders, 1u);
}

TEST(StreamsDescriptorPacks, ADamagedDescriptorIsReportedWithItsSector) {
  const auto body = serialize(sample());
  std::vector<std::int64_t> scr(1, 0);
  auto packs = makeDescriptorPacks(body, {}, 25200, scr);
  packs[14 + 6 + 12 + 30] ^= 1;  // inside the body
  Demuxer dm;
  EXPECT_EQ(dm.feed(packs, 7), 1u);
  ASSERT_EQ(dm.errors().size(), 1u);
  EXPECT_EQ(dm.errors()[0].kind, ErrorKind::BadDescriptor);
  EXPECT_EQ(dm.errors()[0].sector, 7u);
  EXPECT_NE(dm.errors()[0].describe().find("CRC"), std::string::npos);
  EXPECT_FALSE(dm.descriptor());
}

}  // namespace
}  // namespace vbim::streams
