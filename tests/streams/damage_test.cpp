// Truncated, bit-flipped and wrong-format inputs give clear errors (issue #4 item 6), and the reader
// carries on after damage.
#include <gtest/gtest.h>

#include <random>

#include "streams/format.hpp"
#include "streams/pack_parser.hpp"
#include "streams/stream_stats.hpp"
#include "tests/streams/stream_fixture.hpp"

namespace vbim::streams {
namespace {

using test::smallStream;

bool anyError(const StreamScan& scan, ErrorKind kind, std::uint32_t sector, const std::string& words) {
  for (const StreamError& e : scan.errors)
    if (e.kind == kind && e.sector == sector && e.describe().find(words) != std::string::npos) return true;
  return false;
}

std::string all(const StreamScan& scan) {
  std::string s;
  for (const StreamError& e : scan.errors) s += e.describe() + "\n";
  return s;
}

TEST(StreamsDamage, TruncationMidSectorAndAtASectorBoundary) {
  const auto& good = smallStream().bytes;
  auto cut = good;
  cut.resize(good.size() - 3000);  // ends 1096 bytes into a sector
  StreamScan scan = scanStream(cut);
  const auto last = static_cast<std::uint32_t>(cut.size() / kSectorBytes);
  EXPECT_FALSE(scan.every2048);
  EXPECT_TRUE(anyError(scan, ErrorKind::ShortSector, last, "1096 bytes")) << all(scan);
  EXPECT_TRUE(anyError(scan, ErrorKind::ShortSector, last, "truncated")) << all(scan);

  cut.resize(good.size() - 4 * kSectorBytes);  // whole sectors missing: the descriptor knows
  scan = scanStream(cut);
  EXPECT_TRUE(scan.every2048);
  EXPECT_TRUE(anyError(scan, ErrorKind::ShortSector, last - 2, "descriptor says")) << all(scan);
}

TEST(StreamsDamage, AFlippedPackHeaderBitIsReportedAtItsSectorAndReadingContinues) {
  const auto& good = smallStream().bytes;
  auto bad = good;
  const std::uint32_t sector = 5;
  bad[sector * kSectorBytes + 4] ^= 0x04;  // a marker bit of the SCR
  const StreamScan scan = scanStream(bad);
  EXPECT_FALSE(scan.every2048);
  ASSERT_FALSE(scan.errors.empty());
  EXPECT_EQ(scan.errors[0].kind, ErrorKind::BadPackHeader);
  EXPECT_EQ(scan.errors[0].sector, sector);
  EXPECT_EQ(scan.errors[0].byteOffset, sector * kSectorBytes + 4);
  EXPECT_EQ(scan.stats.badSectors, 1u);
  // Exactly the pictures with bytes in the bad sector are lost (those in progress are reported as
  // dropped); all others come out undamaged.
  const StreamScan clean = scanStream(good);
  std::size_t touching = 0;
  for (const PictureRecord& p : clean.pictures) touching += p.firstSector <= sector && sector <= p.lastSector;
  ASSERT_GT(touching, 0u);
  EXPECT_EQ(scan.pictures.size(), clean.pictures.size() - touching);
  EXPECT_GE(scan.stats.droppedPictures, 1u);
  for (const PictureRecord& p : scan.pictures) {
    EXPECT_FALSE(p.damaged);
    EXPECT_TRUE(p.lastSector < sector || p.firstSector > sector);
  }
}

TEST(StreamsDamage, AFlippedPesLengthIsAnOverrunAtItsSector) {
  auto bad = smallStream().bytes;
  const std::uint32_t sector = 3;
  const std::size_t at = sector * kSectorBytes + 14 + (bad[sector * kSectorBytes + 13] & 7) + 4;
  bad[at] |= 0x40;  // PES_packet_length high byte: far past the pack
  const StreamScan scan = scanStream(bad);
  ASSERT_FALSE(scan.errors.empty());
  EXPECT_EQ(scan.errors[0].kind, ErrorKind::PackOverrun) << all(scan);
  EXPECT_EQ(scan.errors[0].sector, sector);
}

TEST(StreamsDamage, AFlippedPictureBitFailsTheIndexCrcWithTheFrameNumber) {
  const auto& s = smallStream();
  auto bad = s.bytes;
  const IndexEntry& e = s.descriptor.index[0][3];  // lightmap frame 3
  // The last byte of the lightmap payload in the picture's first pack.
  const auto pack = std::span(s.bytes).subspan(std::size_t{e.sector} * kSectorBytes, kSectorBytes);
  ParsedPack parsed;
  ASSERT_FALSE(parsePack(pack, e.sector, parsed));
  std::size_t at = 0;
  for (const PesPacket& p : parsed.packets)
    if (p.streamId == kLightmapStream)
      at = std::size_t{e.sector} * kSectorBytes + p.payloadOffset + p.payload.size() - 1;
  ASSERT_GT(at, 0u);
  bad[at] ^= 0x01;
  const StreamScan scan = scanStream(bad);
  bool flagged = false;
  for (const PictureRecord& p : scan.pictures) flagged |= p.damaged;
  EXPECT_TRUE(flagged);
  bool named = false;
  for (const StreamError& err : scan.errors)
    named |= err.kind == ErrorKind::PictureMismatch && err.message.find("CRC") != std::string::npos;
  EXPECT_TRUE(named) << all(scan);
}

TEST(StreamsDamage, AFlippedDescriptorBitIsABadDescriptor) {
  auto bad = smallStream().bytes;
  bad[14 + 20 + 6 + 12 + 60] ^= 0x80;  // inside the descriptor body in pack 0
  const StreamScan scan = scanStream(bad);
  EXPECT_FALSE(scan.descriptor);
  EXPECT_TRUE(anyError(scan, ErrorKind::BadDescriptor, 0, "CRC")) << all(scan);
  EXPECT_FALSE(scan.pictures.empty());  // the video is still readable
}

TEST(StreamsDamage, WrongFormatInputsFailAtSectorZero) {
  // A PNG signature, a text file, an MPEG-1 system stream pack and an empty file.
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  png.resize(4096, 0);
  std::string text = "this is not a stream\n";
  std::vector<std::uint8_t> txt(text.begin(), text.end());
  std::vector<std::uint8_t> mpeg1(kSectorBytes, 0xFF);
  const std::uint8_t h[] = {0, 0, 1, 0xBA, 0x21, 0, 1, 0, 1, 0x80, 0x1B, 0x91};
  std::copy(std::begin(h), std::end(h), mpeg1.begin());
  StreamScan scan = scanStream(png);
  EXPECT_TRUE(anyError(scan, ErrorKind::BadPackHeader, 0, "00 00 01 BA")) << all(scan);
  EXPECT_EQ(scan.stats.badSectors, 2u);
  scan = scanStream(txt);
  EXPECT_TRUE(anyError(scan, ErrorKind::ShortSector, 0, "21 bytes")) << all(scan);
  scan = scanStream(mpeg1);
  EXPECT_TRUE(anyError(scan, ErrorKind::BadPackHeader, 0, "MPEG-1")) << all(scan);
  scan = scanStream({});
  EXPECT_FALSE(scan.every2048);
  EXPECT_TRUE(scan.pictures.empty());
}

TEST(StreamsDamage, ASectorGapDropsThePictureInProgress) {
  const auto& s = smallStream();
  Demuxer dm;
  const std::uint32_t n = s.descriptor.totalSectors;
  for (std::uint32_t lsn = 0; lsn < n; ++lsn) {
    if (lsn == n / 2) continue;  // lost on the way
    dm.feed(std::span(s.bytes).subspan(std::size_t{lsn} * kSectorBytes, kSectorBytes), lsn);
  }
  dm.finish();
  EXPECT_EQ(dm.stats().sectorGaps, 1u);
  EXPECT_GE(dm.stats().droppedPictures, 1u);
  for (const Picture& p : dm.pictures()) EXPECT_FALSE(p.damaged);
}

TEST(StreamsDamage, RandomByteDamageNeverCrashesAndNeverPassesUnnoticed) {
  // Seeded damage anywhere in the stream: the reader must not crash (ASan/UBSan in CI), and every
  // picture it still delivers as undamaged must be exactly the original bytes.
  const auto& s = smallStream();
  const StreamScan clean = scanStream(s.bytes);
  std::mt19937 rng(12345);
  for (int round = 0; round < 60; ++round) {
    auto bad = s.bytes;
    const int flips = 1 + static_cast<int>(rng() % 8);
    for (int i = 0; i < flips; ++i) bad[rng() % bad.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    const StreamScan scan = scanStream(bad);
    if (!scan.descriptor) continue;  // the descriptor itself was hit: reported as BadDescriptor
    for (const PictureRecord& p : scan.pictures) {
      if (p.damaged) continue;
      ASSERT_TRUE(p.frame);
      bool same = false;
      for (const PictureRecord& c : clean.pictures)
        same |= c.streamId == p.streamId && c.frame == p.frame && c.crc == p.crc && c.bytes == p.bytes;
      EXPECT_TRUE(same) << "round " << round;
    }
  }
}

}  // namespace
}  // namespace vbim::streams
