// The whole-file program stream reader: MPEG-1 system streams, MPEG-2 packs of any size, damage and
// truncation reported with their byte offset, and one video stream's bytes taken out with the file
// offset of each.
#include <gtest/gtest.h>

#include <string>

#include "streams/program_stream.hpp"
#include "streams/video_elementary_stream.hpp"
#include "tests/streams/program_stream_builder.hpp"

namespace vbim::streams {
namespace {

using testing::append;
using testing::Bytes;

Bytes counting(std::size_t n, std::uint8_t first) {
  Bytes b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(first + i);
  return b;
}

std::vector<ParsedPack> readAll(ProgramStreamReader& r, std::vector<std::size_t>* offsets = nullptr) {
  std::vector<ParsedPack> packs;
  ParsedPack p;
  while (r.next(p)) {
    packs.push_back(p);
    if (offsets) offsets->push_back(r.packOffset());
  }
  return packs;
}

std::string all(const std::vector<StreamError>& errors) {
  std::string s;
  for (const StreamError& e : errors) s += e.describe() + "\n";
  return s;
}

// The first 12 bytes of an MPEG-1 system stream as Debian 12's ffmpeg (5.1, `-f mpeg`) writes them.
TEST(StreamsProgramStream, ReadsAnMpeg1PackHeaderAsFfmpegWritesIt) {
  Bytes s = {0x00, 0x00, 0x01, 0xBA, 0x21, 0x00, 0x01, 0x00, 0x01, 0x88, 0x66, 0x99};
  append(s, {0x00, 0x00, 0x01, 0xB9});
  ParsedPack p;
  ASSERT_FALSE(parsePackAt(s, 0, p));
  EXPECT_TRUE(p.mpeg1);
  EXPECT_EQ(p.scr27MHz, 0);
  EXPECT_EQ(p.muxRate, (0x08u << 15) | (0x66u << 7) | (0x99u >> 1));
  EXPECT_TRUE(p.hasEndCode);
  EXPECT_EQ(p.size, 16u);
}

TEST(StreamsProgramStream, ReadsAnMpeg1SystemStream) {
  // One pack header, a system header, then packets with no further pack header: MPEG-1 PES headers
  // with stuffing, STD buffer size, PTS, PTS and DTS, or 0x0F; an audio packet; padding; end code.
  Bytes s = testing::mpeg1PackHeader(90000, 3000);
  append(s, testing::systemHeader());
  const std::size_t first = s.size();
  append(s, testing::mpeg1Pes(0xE0, counting(100, 0), 3600, std::nullopt, 2, true));
  append(s, testing::mpeg1Pes(0xC0, counting(50, 0x80)));
  append(s, testing::mpeg1Pes(0xE0, counting(70, 100), 7200, 3600));
  const std::size_t third = s.size();
  append(s, testing::mpeg1Pes(0xE0, counting(30, 170)));
  append(s, testing::padding(40));
  append(s, {0, 0, 1, 0xB9});
  append(s, {0x12, 0x34});  // after the end code: not read

  ProgramStreamReader r(s);
  const std::vector<ParsedPack> packs = readAll(r);
  ASSERT_EQ(packs.size(), 1u) << all(r.defects());
  EXPECT_TRUE(r.defects().empty()) << all(r.defects());
  const ParsedPack& p = packs[0];
  EXPECT_TRUE(p.mpeg1);
  EXPECT_EQ(p.scr27MHz, 90000 * 300);
  EXPECT_EQ(p.muxRate, 3000u);
  EXPECT_TRUE(p.hasSystemHeader);
  EXPECT_TRUE(p.hasEndCode);
  EXPECT_EQ(p.size, s.size() - 2);
  ASSERT_EQ(p.packets.size(), 5u);
  EXPECT_EQ(p.packets[0].offset, first);
  EXPECT_EQ(p.packets[0].payloadOffset, first + 6 + 2 + 2 + 5);
  EXPECT_EQ(p.packets[0].pts, 3600);
  EXPECT_EQ(p.packets[0].payload.size(), 100u);
  EXPECT_EQ(p.packets[1].streamId, 0xC0);
  EXPECT_FALSE(p.packets[1].pts);
  EXPECT_EQ(p.packets[2].pts, 7200);  // the PTS, not the DTS after it
  EXPECT_EQ(p.packets[2].payload.size(), 70u);
  EXPECT_EQ(p.packets[3].payload[0], 170);
  EXPECT_EQ(p.packets[4].streamId, 0xBE);

  const VideoElementaryStream v = readVideoStream(s);
  ASSERT_EQ(v.streamId, 0xE0);
  EXPECT_EQ(v.bytes, counting(200, 0));
  EXPECT_EQ(v.fileOffsetOf(0), first + 6 + 9);
  EXPECT_EQ(v.fileOffsetOf(170), third + 6 + 1);  // first byte of the last packet's payload
  EXPECT_EQ(v.fileOffsetOf(199), third + 6 + 1 + 29);
}

TEST(StreamsProgramStream, ReadsMpeg2PacksOfAnySize) {
  // Packs of 1000 bytes as `ffmpeg -f vob -packetsize 1000` writes them, and of odd sizes, with pack
  // stuffing; the reader follows the packets, not a fixed pack size.
  const Bytes es = counting(2500, 7);
  for (const std::size_t packBytes : {std::size_t{1000}, std::size_t{777}, std::size_t{2049}, std::size_t{64}}) {
    SCOPED_TRACE(packBytes);
    const Bytes s = testing::muxMpeg2(es, 0xE0, packBytes);
    ProgramStreamReader r(s);
    std::vector<std::size_t> offsets;
    const std::vector<ParsedPack> packs = readAll(r, &offsets);
    EXPECT_TRUE(r.defects().empty()) << all(r.defects());
    ASSERT_EQ(packs.size(), (s.size() + packBytes - 1) / packBytes);
    for (std::size_t i = 0; i < packs.size(); ++i) {
      EXPECT_EQ(offsets[i], i * packBytes);
      EXPECT_EQ(packs[i].size, packBytes);
      EXPECT_FALSE(packs[i].mpeg1);
      EXPECT_EQ(packs[i].scr27MHz, static_cast<std::int64_t>(300 * 3600 * i));
      EXPECT_EQ(packs[i].hasSystemHeader, i == 0);
    }
    EXPECT_EQ(packs[0].packets[0].pts, 3600);
    const VideoElementaryStream v = readVideoStream(s, 0xE0);
    EXPECT_EQ(v.bytes, es);
    // Every byte maps back to the byte of the file that holds it.
    for (std::size_t i = 0; i < es.size(); i += 97) EXPECT_EQ(s[v.fileOffsetOf(i)], es[i]) << i;
  }
}

TEST(StreamsProgramStream, TakesTheVideoStreamAskedFor) {
  Bytes s = testing::mpeg2PackHeader(0, 2500);
  append(s, testing::mpeg2Pes(0xC0, counting(10, 0)));
  append(s, testing::mpeg2Pes(0xE0, counting(10, 20)));
  append(s, testing::mpeg2Pes(0xE1, counting(10, 40)));
  append(s, testing::mpeg2Pes(0xE0, counting(10, 30)));
  EXPECT_EQ(readVideoStream(s).streamId, 0xE0);
  EXPECT_EQ(readVideoStream(s).bytes, counting(20, 20));
  EXPECT_EQ(readVideoStream(s, 0xE1).bytes, counting(10, 40));
  EXPECT_FALSE(readVideoStream(s, 0xE2).streamId);
  Bytes audioOnly = testing::mpeg2PackHeader(0, 2500);
  append(audioOnly, testing::mpeg2Pes(0xC0, counting(10, 0)));
  EXPECT_FALSE(readVideoStream(audioOnly).streamId);
}

TEST(StreamsProgramStream, ATruncatedPackIsReportedWithItsByteOffset) {
  const Bytes whole = testing::muxMpeg2(counting(2500, 7), 0xE0, 1000);
  struct Cut {
    std::size_t at;          // bytes kept
    std::size_t defectAt;    // byte offset named
    const char* words;       // in the message
    std::size_t videoBytes;  // elementary-stream bytes still read
  };
  // The second pack starts at 1000 (header 14 + 1 stuffing, PES header 9): its payload at 1024.
  const Cut cuts[] = {
      {1005, 1000, "pack header of 14 bytes cut", 1000 - 14 - 15 - 14},
      {1014, 1000, "pack header of 15 bytes cut", 1000 - 14 - 15 - 14},
      {1002, 1000, "the last 2 bytes are too few for a start code", 1000 - 14 - 15 - 14},
      {1017, 1015, "the last 2 bytes are too few for a start code", 1000 - 14 - 15 - 14},
      {1020, 1015, "PES header cut", 1000 - 14 - 15 - 14},
      {1500, 1015, "runs past the end of the data by 500 bytes", 1000 - 14 - 15 - 14 + 1500 - 1024},
  };
  for (const Cut& c : cuts) {
    SCOPED_TRACE(c.at);
    const Bytes s(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(c.at));
    ProgramStreamReader r(s);
    readAll(r);
    ASSERT_EQ(r.defects().size(), 1u) << all(r.defects());
    const StreamError& e = r.defects()[0];
    EXPECT_EQ(e.kind, ErrorKind::Truncated);
    EXPECT_EQ(e.byteOffset, c.defectAt);
    EXPECT_NE(e.message.find(c.words), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("truncated"), std::string::npos) << e.message;
    EXPECT_NE(e.describe().find("byte " + std::to_string(c.defectAt)), std::string::npos) << e.describe();
    // What there is of a cut packet is kept.
    EXPECT_EQ(readVideoStream(s).bytes.size(), c.videoBytes);
  }
}

TEST(StreamsProgramStream, SkipsADamagedPackAndReadsOn) {
  Bytes s = testing::mpeg2PackHeader(0, 2500);
  append(s, testing::mpeg2Pes(0xE0, counting(10, 0)));
  const std::size_t damaged = s.size();
  append(s, testing::mpeg2Pes(0xE0, counting(10, 10)));
  s[damaged + 2] = 0x00;  // 00 00 00 E0: not a start code
  const std::size_t next = s.size();
  append(s, testing::mpeg2PackHeader(0, 2500));
  append(s, testing::mpeg2Pes(0xE0, counting(10, 20)));
  ProgramStreamReader r(s);
  std::vector<std::size_t> offsets;
  const std::vector<ParsedPack> packs = readAll(r, &offsets);
  ASSERT_EQ(r.defects().size(), 1u) << all(r.defects());
  EXPECT_EQ(r.defects()[0].kind, ErrorKind::BadPes);
  EXPECT_EQ(r.defects()[0].byteOffset, damaged);
  EXPECT_NE(r.defects()[0].message.find("skipping to the next pack at byte " + std::to_string(next)), std::string::npos)
      << r.defects()[0].message;
  // The packets before the defect are read, and so is the pack after it.
  ASSERT_EQ(packs.size(), 2u);
  EXPECT_EQ(packs[0].packets.size(), 1u);
  EXPECT_EQ(offsets[1], next);
  Bytes video = counting(10, 0);
  append(video, counting(10, 20));
  EXPECT_EQ(readVideoStream(s).bytes, video);
}

TEST(StreamsProgramStream, SkipsToTheNextPackStartCode) {
  const Bytes s = testing::muxMpeg2(counting(2500, 7), 0xE0, 1000);
  Bytes junk = s;
  junk[1000] = 0x47;  // pack 1 loses its start code: skipped whole
  ProgramStreamReader j(junk);
  std::vector<std::size_t> offsets;
  const std::vector<ParsedPack> rest = readAll(j, &offsets);
  ASSERT_EQ(j.defects().size(), 1u) << all(j.defects());
  EXPECT_EQ(j.defects()[0].kind, ErrorKind::BadPes);  // where pack 0's packets should go on
  EXPECT_EQ(j.defects()[0].byteOffset, 1000u);
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(offsets[1], 2000u);
}

TEST(StreamsProgramStream, RejectsAnMpeg1PesHeaderWithoutItsTimestampField) {
  Bytes s = testing::mpeg1PackHeader(0, 3000);
  const std::size_t at = s.size();
  append(s, testing::packet(0xE0, {0xFF, 0x87}, counting(10, 0)));  // stuffing, then neither STD, PTS nor 0x0F
  ParsedPack p;
  const auto e = parsePackAt(s, 0, p);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->kind, ErrorKind::BadPes);
  EXPECT_EQ(e->byteOffset, at + 7);
  EXPECT_NE(e->message.find("0x0F"), std::string::npos) << e->message;
}

TEST(StreamsProgramStream, TellsTheFormOfAFile) {
  EXPECT_EQ(detectStreamForm(testing::mpeg1PackHeader(0, 1)), StreamForm::ProgramStream);
  EXPECT_EQ(detectStreamForm(Bytes{0, 0, 1, 0xB3, 1, 2}), StreamForm::ElementaryStream);
  EXPECT_EQ(detectStreamForm(Bytes{7, 0, 0, 1, 0xB3}), StreamForm::ElementaryStream);
  EXPECT_EQ(detectStreamForm(Bytes{1, 2, 3, 4, 5}), StreamForm::NotMpeg);
  EXPECT_EQ(detectStreamForm(Bytes{}), StreamForm::NotMpeg);
  const VideoElementaryStream raw = rawVideoStream(Bytes{0, 0, 1, 0xB3});
  EXPECT_FALSE(raw.streamId);
  EXPECT_EQ(raw.fileOffsetOf(3), 3u);
}

TEST(StreamsProgramStream, NoInputMakesItReadOutOfBounds) {
  // Every single-byte change and every cut of a small stream of both forms reads without crashing
  // (ASan/UBSan in CI would catch an out-of-bounds read).
  const Bytes forms[] = {testing::muxMpeg2(counting(300, 0), 0xE0, 128), testing::muxMpeg1(counting(300, 0), 0xE0, 90)};
  for (const Bytes& good : forms) {
    for (std::size_t at = 0; at < good.size(); ++at) {
      for (std::uint8_t v : {std::uint8_t{0x00}, std::uint8_t{0x01}, std::uint8_t{0xFF}, std::uint8_t{0xBA}}) {
        Bytes s = good;
        s[at] = v;
        (void)readVideoStream(s);
      }
      (void)readVideoStream(std::span(good).first(at));
    }
  }
}

}  // namespace
}  // namespace vbim::streams
