// Item 6 of issue #4: author -> our reader (sector by sector) -> libavcodec decode, PSNR >= 40 dB at
// the default quality; every pack 2048 bytes; the index points at the right sectors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "streams/authoring/bench_stream.hpp"
#include "streams/authoring/error.hpp"
#include "streams/authoring/mpeg2_decoder.hpp"
#include "streams/authoring/mpeg2_encoder.hpp"
#include "streams/demuxer.hpp"
#include "streams/format.hpp"
#include "streams/stream_stats.hpp"
#include "tests/streams/stream_fixture.hpp"

namespace vbim::streams {
namespace {

using test::smallStream;

std::span<const std::uint8_t> sectorOf(const std::vector<std::uint8_t>& bytes, std::uint32_t lsn) {
  return std::span(bytes).subspan(std::size_t{lsn} * kSectorBytes, kSectorBytes);
}

TEST(StreamsRoundTrip, EveryPictureDecodesAbove40DbAtTheDefaultQuality) {
  const auto& s = smallStream();
  Demuxer dm;
  for (std::uint32_t lsn = 0; lsn * kSectorBytes < s.bytes.size(); ++lsn)
    EXPECT_EQ(dm.feed(sectorOf(s.bytes, lsn), lsn), 0u);
  dm.finish();
  ASSERT_TRUE(dm.descriptor());
  EXPECT_TRUE(dm.errors().empty());
  const std::uint32_t total = s.descriptor.totalFrames();
  std::vector<int> seen(2 * total, 0);
  // The codec round trip is measured on the Y, Cb, Cr planes against the encoder's own input (the
  // usual codec measure); RGB PSNR also contains the 4:2:0 chroma subsampling the format mandates, and is
  // only recorded.
  Mpeg2Decoder dec;
  double worst = 1e9, worstRgb = 1e9;
  for (const Picture& p : dm.pictures()) {
    ASSERT_TRUE(p.frame);
    EXPECT_FALSE(p.damaged);
    const bool sky = p.streamId == kSkyStream;
    ++seen[(sky ? total : 0) + *p.frame];
    const Rgba8Image& want = sky ? s.skies[*p.frame] : s.lightmaps[*p.frame];
    const Yuv420Image got = dec.decodeYuv(p.data);
    EXPECT_EQ(dec.lastPictureType(), 'I');
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    const PlanePsnr psnr = psnrYuv(got, rgbaToYuv420(want));
    worst = std::min(worst, psnr.min());
    worstRgb = std::min(worstRgb, psnrRgb(dec.decodeRgba(p.data), want));
    EXPECT_GE(psnr.min(), 40.0) << "stream " << int(p.streamId) << " frame " << *p.frame << ": Y " << psnr.y << " Cb "
                                << psnr.cb << " Cr " << psnr.cr;
  }
  RecordProperty("worst_plane_psnr_db", std::to_string(worst));
  RecordProperty("worst_rgb_psnr_db", std::to_string(worstRgb));
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "picture " << i;
}

TEST(StreamsRoundTrip, EveryPackIs2048BytesAndSumsExactly) {
  // An independent walker (not the reader): each 2048-byte slice starts with an MPEG-2 pack header
  // and its packets' lengths add up to exactly 2048.
  const auto& b = smallStream().bytes;
  ASSERT_EQ(b.size() % kSectorBytes, 0u);
  std::size_t pes = 0;
  for (std::size_t at = 0; at < b.size(); at += kSectorBytes) {
    ASSERT_EQ(b[at] << 16 | b[at + 1] << 8 | b[at + 2], 1) << "sector " << at / kSectorBytes;
    ASSERT_EQ(b[at + 3], 0xBA);
    ASSERT_EQ(b[at + 4] & 0xC0, 0x40);
    std::size_t pos = 14 + (b[at + 13] & 7);
    while (pos < kSectorBytes) {
      ASSERT_EQ(b[at + pos] << 16 | b[at + pos + 1] << 8 | b[at + pos + 2], 1);
      pos += 6 + (b[at + pos + 4] << 8 | b[at + pos + 5]);
      ++pes;
    }
    EXPECT_EQ(pos, kSectorBytes) << "sector " << at / kSectorBytes;
  }
  EXPECT_GT(pes, b.size() / kSectorBytes);
}

TEST(StreamsRoundTrip, TheIndexPointsAtTheSectorWhereEachPictureBegins) {
  const auto& s = smallStream();
  const Descriptor& d = s.descriptor;
  EXPECT_EQ(d.totalSectors * kSectorBytes, s.bytes.size());
  EXPECT_EQ(d.variants.size(), 2u);
  EXPECT_EQ(d.variants[1].firstFrame, d.framesPerVariant);
  for (std::size_t st = 0; st < d.streams.size(); ++st) {
    for (std::uint32_t f = 0; f < d.totalFrames(); ++f) {
      const IndexEntry& e = d.index[st][f];
      // Seek there as a player would, with the descriptor it already has, and read on: frame f must
      // come out whole and undamaged (an earlier picture may start in the same sector).
      Demuxer dm;
      dm.setDescriptor(d);
      std::optional<Picture> found;
      auto take = [&] {
        for (Picture& p : dm.pictures())
          if (p.streamId == d.streams[st].id && p.frame == f) found = std::move(p);
        dm.pictures().clear();
      };
      for (std::uint32_t lsn = e.sector; lsn < d.totalSectors && !found; ++lsn) {
        dm.feed(sectorOf(s.bytes, lsn), lsn);
        take();
      }
      if (!found) {
        dm.finish();
        take();
      }
      ASSERT_TRUE(found) << "stream " << st << " frame " << f;
      EXPECT_EQ(found->firstSector, e.sector);
      EXPECT_EQ(found->byteOffset, std::uint64_t{e.sector} * kSectorBytes + e.offset);
      EXPECT_EQ(found->data.size(), e.bytes);
      EXPECT_FALSE(found->damaged);
      EXPECT_TRUE(dm.errors().empty()) << dm.errors().front().describe();
      // Seeking one sector too late loses the frame: the index is not merely an upper bound.
      if (f > 0 && e.offset > 0) {
        Demuxer late;
        late.setDescriptor(d);
        bool again = false;
        for (std::uint32_t lsn = e.sector + 1; lsn < d.totalSectors; ++lsn) {
          late.feed(sectorOf(s.bytes, lsn), lsn);
          for (const Picture& p : late.pictures()) again |= p.streamId == d.streams[st].id && p.frame == f;
        }
        EXPECT_FALSE(again) << "stream " << st << " frame " << f;
      }
    }
  }
  // A variant's first sector holds data of its first frame.
  for (const Variant& v : d.variants) {
    std::uint32_t first = UINT32_MAX;
    for (const auto& table : d.index) first = std::min(first, table[v.firstFrame].sector);
    EXPECT_EQ(v.firstSector, first);
  }
}

TEST(StreamsRoundTrip, AuthoringIsDeterministic) {
  // Same frames, same bytes (fresh writer, same settings as the fixture).
  const auto& s = smallStream(3, 1);
  AuthorSettings settings;
  settings.gameFps = {2, 1};
  settings.loopFrame = 1;
  StreamWriter w(settings);
  w.beginVariant("clear");
  for (std::size_t i = 0; i < 3; ++i) w.addFrame(s.lightmaps[i], &s.skies[i]);
  EXPECT_EQ(w.finish(), s.bytes);
}

// Frames larger than the DVD mux rate carries in one 25 fps period (here ~200 KB of noise per
// frame against ~50 KB) are spread in container time, so the muxer keeps each frame's lightmap and
// sky pictures together: without that, the sky fell further behind every frame (330 sectors after
// 16 frames, 1,400 after 64), and the EE demux had to hold everything in between.
TEST(StreamsRoundTrip, LightmapAndSkyStayInStepWhenFramesExceedTheMuxRate) {
  const auto bytes = vbim::streams::authorBenchStream(16, vbim::streams::BenchContent::Noise, 1);
  const StreamScan scan = scanStream(bytes);
  ASSERT_TRUE(scan.descriptor);
  const Descriptor& d = *scan.descriptor;
  EXPECT_GT(d.ptsPerFrame, 3600u) << "the container time should have been stretched";
  EXPECT_EQ(d.ptsPerFrame % 3600, 0u) << "by a whole number of 25 fps periods";
  ASSERT_EQ(d.index.size(), 2u);
  std::int64_t widest = 0;
  for (std::uint32_t f = 0; f < d.totalFrames(); ++f) {
    const std::int64_t lightmapEnd = d.index[0][f].sector + d.index[0][f].bytes / 2048;
    const std::int64_t skyEnd = d.index[1][f].sector + d.index[1][f].bytes / 2048;
    widest = std::max(widest, std::abs(lightmapEnd - skyEnd));
  }
  // One frame's two pictures are ~130 sectors together: their ends stay within that.
  EXPECT_LT(widest, 150) << "frame pictures drifted apart in the mux";
}

TEST(StreamsRoundTrip, AFixedQuantiserIsHonouredAndCoarserMeansSmaller) {
  const auto& s = smallStream(3, 1);
  std::vector<std::size_t> sizes;
  for (int q : {2, 8, 20}) {
    AuthorSettings settings;
    settings.encoder.qscale = q;
    StreamWriter w(settings);
    for (std::size_t i = 0; i < 3; ++i) w.addFrame(s.lightmaps[i], &s.skies[i]);
    const auto bytes = w.finish();
    EXPECT_EQ(w.maxQscaleUsed(), q);  // frame->quality set, no VBV re-quantising
    std::size_t es = 0;
    for (const auto& t : w.descriptor().index)
      for (const IndexEntry& e : t) es += e.bytes;
    sizes.push_back(es);
  }
  EXPECT_GT(sizes[0], sizes[1]);
  EXPECT_GT(sizes[1], sizes[2]);
}

TEST(StreamsRoundTrip, ABitrateTargetRunsWithTheDvdVbv) {
  const auto& s = smallStream(8, 1);
  AuthorSettings settings;
  settings.encoder.bitrate = 400'000;
  StreamWriter w(settings);
  for (std::size_t i = 0; i < 8; ++i) w.addFrame(s.lightmaps[i], &s.skies[i]);
  const auto bytes = w.finish();
  const StreamScan scan = scanStream(bytes);
  EXPECT_TRUE(scan.every2048);
  EXPECT_TRUE(scan.errors.empty());
  EXPECT_EQ(scan.muxRate, 25200u);  // the DVD mux rate, not the muxer's 880 Mbit/s default
}

TEST(StreamsStreamWriter, RejectsBadFramesWithMessagesThatSayWhy) {
  AuthorSettings settings;
  StreamWriter w(settings);
  Rgba8Image odd(33, 32), a(32, 32), b(48, 32), sky(32, 16);
  try {
    w.addFrame(odd, &sky);
    FAIL();
  } catch (const AuthoringError& e) {
    EXPECT_NE(std::string(e.what()).find("33x32"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("multiples of 16"), std::string::npos) << e.what();
  }
  w.addFrame(a, &sky);
  try {
    w.addFrame(b, &sky);
    FAIL();
  } catch (const AuthoringError& e) {
    EXPECT_NE(std::string(e.what()).find("48x32"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("32x32"), std::string::npos) << e.what();
  }
  EXPECT_THROW(w.addFrame(a), AuthoringError);  // the stream has a sky
  w.beginVariant("rain");
  w.addFrame(a, &sky);
  w.addFrame(a, &sky);
  EXPECT_THROW(w.beginVariant("fog"), AuthoringError);  // "rain" has 2 frames, "default" 1
  settings.encoder.containerFps = {24000, 1001};
  EXPECT_THROW(StreamWriter{settings}, AuthoringError);
}

}  // namespace
}  // namespace vbim::streams
