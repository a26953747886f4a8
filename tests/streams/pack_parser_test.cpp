#include <gtest/gtest.h>

#include "streams/descriptor_packs.hpp"
#include "streams/format.hpp"
#include "streams/pack_parser.hpp"

namespace vbim::streams {
namespace {

// A pack with one video PES (PTS 90000) of `videoBytes` payload bytes, then padding to 2048.
std::vector<std::uint8_t> videoPack(std::size_t videoBytes, std::int64_t scr = 123456789) {
  std::vector<std::uint8_t> p(kSectorBytes, 0);
  writePackHeader(p.data(), scr, 25200);
  std::size_t pos = kPackHeaderBytes;
  const std::size_t len = 3 + 5 + videoBytes;
  const std::uint8_t hdr[] = {0, 0, 1, kLightmapStream, static_cast<std::uint8_t>(len >> 8),
                              static_cast<std::uint8_t>(len), 0x81, 0x80, 5,
                              // PTS 90000 = 0x15F90, '0010' prefix
                              0x21, 0x00, 0x05, 0xBF, 0x21};
  std::copy(std::begin(hdr), std::end(hdr), p.begin() + pos);
  pos += sizeof hdr;
  for (std::size_t i = 0; i < videoBytes; ++i) p[pos + i] = static_cast<std::uint8_t>(0x40 + i % 64);
  pos += videoBytes;
  const std::size_t pad = kSectorBytes - pos - 6;
  const std::uint8_t padHdr[] = {
      0, 0, 1, kPaddingStream, static_cast<std::uint8_t>(pad >> 8), static_cast<std::uint8_t>(pad)};
  std::copy(std::begin(padHdr), std::end(padHdr), p.begin() + pos);
  std::fill(p.begin() + pos + 6, p.end(), 0xFF);
  return p;
}

TEST(StreamsPackParser, ReadsHeaderTimestampsAndPackets) {
  const auto p = videoPack(100);
  ParsedPack out;
  ASSERT_FALSE(parsePack(p, 3, out));
  EXPECT_EQ(out.scr27MHz, 123456789);
  EXPECT_EQ(out.muxRate, 25200u);
  ASSERT_EQ(out.packets.size(), 2u);
  EXPECT_EQ(out.packets[0].streamId, kLightmapStream);
  ASSERT_TRUE(out.packets[0].pts);
  EXPECT_EQ(*out.packets[0].pts, 90000);
  EXPECT_EQ(out.packets[0].payload.size(), 100u);
  EXPECT_EQ(out.packets[0].payload[0], 0x40);
  EXPECT_EQ(out.packets[1].streamId, kPaddingStream);
}

TEST(StreamsPackParser, ScrRoundTripsThroughTheHeaderBits) {
  for (std::int64_t scr :
       {std::int64_t{0}, std::int64_t{299}, std::int64_t{300} * ((std::int64_t{1} << 33) - 1) + 299}) {
    const auto p = videoPack(10, scr);
    ParsedPack out;
    ASSERT_FALSE(parsePack(p, 0, out));
    EXPECT_EQ(out.scr27MHz, scr);
  }
}

struct Case {
  const char* name;
  std::size_t at;
  std::uint8_t value;
  ErrorKind kind;
  const char* words;
};

TEST(StreamsPackParser, MalformedPacksNameTheKindOffsetAndSector) {
  const Case cases[] = {
      {"pack start code", 3, 0xBB, ErrorKind::BadPackHeader, "00 00 01 BA"},
      {"MPEG-1 pack", 4, 0x21, ErrorKind::BadPackHeader, "MPEG-1"},
      {"marker bit", 6, 0x00, ErrorKind::BadPackHeader, "marker"},
      {"PES start code", 14, 0x07, ErrorKind::BadPes, "start code"},
      {"PES length overrun", 18, 0x09, ErrorKind::PackOverrun, "overruns"},
      {"MPEG-1 PES header", 20, 0x0F, ErrorKind::BadPes, "MPEG-2"},
      {"PTS marker", 23, 0x20, ErrorKind::BadPes, "PTS"},
  };
  for (const Case& c : cases) {
    auto p = videoPack(100);
    p[c.at] = c.value;
    ParsedPack out;
    const auto err = parsePack(p, 42, out);
    ASSERT_TRUE(err) << c.name;
    EXPECT_EQ(err->kind, c.kind) << c.name << ": " << err->describe();
    EXPECT_EQ(err->sector, 42u);
    EXPECT_GE(err->byteOffset, 42u * 2048);
    EXPECT_LT(err->byteOffset, 43u * 2048);
    EXPECT_NE(err->describe().find(c.words), std::string::npos) << c.name << ": " << err->describe();
    EXPECT_NE(err->describe().find("sector 42"), std::string::npos);
  }
}

TEST(StreamsPackParser, ShortSectorIsATruncation) {
  auto p = videoPack(100);
  p.resize(1000);
  ParsedPack out;
  const auto err = parsePack(p, 9, out);
  ASSERT_TRUE(err);
  EXPECT_EQ(err->kind, ErrorKind::ShortSector);
  EXPECT_NE(err->message.find("truncated"), std::string::npos);
}

TEST(StreamsPackParser, EndCodeEndsThePack) {
  auto p = videoPack(100);
  const std::size_t pad = 14 + 14 + 100;
  p[pad + 3] = kProgramEndCode;
  ParsedPack out;
  ASSERT_FALSE(parsePack(p, 0, out));
  EXPECT_TRUE(out.hasEndCode);
  EXPECT_EQ(out.packets.size(), 1u);
}

TEST(StreamsPackParser, NoInputMakesItReadOutOfBounds) {
  // Every single-byte corruption of a valid pack either parses or yields an error, never a crash
  // (ASan/UBSan in CI would catch an out-of-bounds read).
  const auto good = videoPack(300);
  for (std::size_t at = 0; at < 200; ++at)
    for (std::uint8_t v : {std::uint8_t{0x00}, std::uint8_t{0x01}, std::uint8_t{0xFF}, std::uint8_t{0xBA}}) {
      auto p = good;
      p[at] = v;
      ParsedPack out;
      (void)parsePack(p, 0, out);
    }
}

}  // namespace
}  // namespace vbim::streams
