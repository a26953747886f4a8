// Streams with P and B pictures (issue #29, item 4): what StreamWriter writes with a GOP, what the
// descriptor (version 2) says of each frame, and what the reader and `vbim info`'s summary find.
#include <gtest/gtest.h>

#include <string>

#include "streams/authoring/error.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"
#include "streams/crc32.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::streams {
namespace {

struct GopCase {
  int gop = 6, bFrames = 2;
  bool openGop = false;
  std::uint32_t frames = 14, loop = 4;
  int variants = 2;
};

struct Authored {
  std::vector<std::uint8_t> bytes;
  Descriptor descriptor;
};

Authored author(const GopCase& c) {
  AuthorSettings s;
  s.gameFps = {2, 1};
  s.loopFrame = c.loop;
  s.encoder.gop = c.gop;
  s.encoder.bFrames = c.bFrames;
  s.encoder.openGop = c.openGop;
  StreamWriter w(s);
  SyntheticDay day;
  day.width = 128;
  day.height = 128;
  day.skyWidth = 64;
  day.skyHeight = 32;
  day.frames = c.frames;
  const char* names[] = {"clear", "overcast"};
  for (int v = 0; v < c.variants; ++v) {
    day.weather = names[v];
    w.beginVariant(names[v]);
    for (std::uint32_t f = 0; f < c.frames; ++f) {
      const Rgba8Image lm = toneMap(syntheticLightmap(day, f), ToneMapping{});
      const Rgba8Image sky = toneMap(syntheticSky(day, f), ToneMapping{});
      w.addFrame(lm, &sky);
    }
  }
  Authored a;
  a.bytes = w.finish();
  a.descriptor = w.descriptor();
  return a;
}

std::size_t count(const Descriptor& d, PictureType t) {
  std::size_t n = 0;
  for (const auto& table : d.index)
    for (const IndexEntry& e : table) n += e.type == t;
  return n;
}

// Every frame of every stream is found by the reader at its index entry, undamaged; the descriptor
// survives its own serialisation; variants and the loop frame start GOPs.
void expectWellIndexed(const Authored& a, const GopCase& c) {
  const Descriptor& d = a.descriptor;
  const StreamScan scan = scanStream(a.bytes);
  EXPECT_TRUE(scan.errors.empty()) << scan.errors.front().describe();
  ASSERT_TRUE(scan.descriptor);
  EXPECT_EQ(*scan.descriptor, d);
  const std::vector<std::uint8_t> body = serialize(d);
  EXPECT_EQ(body[1], Descriptor::kVersion);  // big-endian u16 version
  const DescriptorParse back = parseDescriptor(body);
  ASSERT_TRUE(back.descriptor) << back.error;
  EXPECT_EQ(*back.descriptor, d);
  std::vector<std::vector<bool>> seen(d.streams.size(), std::vector<bool>(d.totalFrames()));
  for (const PictureRecord& p : scan.pictures) {
    ASSERT_TRUE(p.frame);
    EXPECT_FALSE(p.damaged);
    ASSERT_TRUE(p.header);
    const auto s = static_cast<std::size_t>(d.streamIndex(p.streamId));
    EXPECT_EQ(p.header->type, d.index[s][*p.frame].type) << "frame " << *p.frame;
    seen[s][*p.frame] = true;
  }
  for (const auto& table : seen)
    for (bool b : table) EXPECT_TRUE(b);
  for (std::size_t s = 0; s < d.streams.size(); ++s) {
    for (int v = 0; v < c.variants; ++v) {
      const std::uint32_t first = static_cast<std::uint32_t>(v) * c.frames;
      EXPECT_TRUE(d.index[s][first].gopStart);
      EXPECT_EQ(d.index[s][first].type, PictureType::I);
      EXPECT_TRUE(d.index[s][first + c.loop].gopStart);
      for (std::uint32_t f = 0; f < c.frames; ++f) {
        const std::uint32_t r = d.resumeFrame(s, first + f);
        EXPECT_GE(r, first);
        EXPECT_LE(r, first + f);
        EXPECT_TRUE(d.index[s][r].gopStart);
        // No GOP starts between the resume frame and the frame.
        for (std::uint32_t g = r + 1; g <= first + f; ++g) EXPECT_FALSE(d.index[s][g].gopStart);
      }
    }
  }
}

TEST(GopStream, ClosedGopsWithBPicturesAreIndexedInDisplayOrder) {
  const GopCase c;
  const Authored a = author(c);
  expectWellIndexed(a, c);
  const Descriptor& d = a.descriptor;
  EXPECT_FALSE(d.intraOnly());
  EXPECT_GT(count(d, PictureType::P), 0u);
  EXPECT_GT(count(d, PictureType::B), 0u);
  for (const auto& table : d.index)
    for (const IndexEntry& e : table) {
      EXPECT_TRUE(!e.gopStart || e.closedGop);
    }
  // B pictures follow, in the file, the reference shown after them: frame order is not file order.
  bool reordered = false;
  for (std::uint32_t g = 1; g < d.totalFrames(); ++g) {
    const IndexEntry &a0 = d.index[0][g - 1], &a1 = d.index[0][g];
    reordered |= a1.sector < a0.sector || (a1.sector == a0.sector && a1.offset < a0.offset);
  }
  EXPECT_TRUE(reordered);
}

TEST(GopStream, GopLengthAndPatternAreAsAsked) {
  GopCase c;
  c.variants = 1;
  c.loop = 0;
  c.frames = 24;
  const Authored a = author(c);
  expectWellIndexed(a, c);
  const StreamScan scan = scanStream(a.bytes);
  const auto reports = summarise(scan, 2.0, 1);
  ASSERT_EQ(reports.size(), 2u);
  for (const StreamReport& r : reports) {
    EXPECT_EQ(r.gops, 4u);
    EXPECT_EQ(r.closedGops, 4u);
    EXPECT_EQ(r.gopPictures.min, 6);
    EXPECT_EQ(r.gopPictures.max, 6);
    EXPECT_EQ(r.types[0].pictures, 4u);
    EXPECT_EQ(r.types[0].pictures + r.types[1].pictures + r.types[2].pictures, 24u);
    EXPECT_GT(r.types[2].pictures, 0u);
    ASSERT_FALSE(r.shapes.empty());
    EXPECT_EQ(r.shapes.front().pattern.size(), 6u);
    EXPECT_EQ(r.shapes.front().pattern[0], 'I');
    // I pictures carry more bits than the predicted ones on this slowly changing content.
    EXPECT_GT(r.types[0].bytes.mean, r.types[2].bytes.mean);
  }
}

TEST(GopStream, PPicturesOnly) {
  GopCase c;
  c.bFrames = 0;
  c.gop = 5;
  const Authored a = author(c);
  expectWellIndexed(a, c);
  EXPECT_GT(count(a.descriptor, PictureType::P), 0u);
  EXPECT_EQ(count(a.descriptor, PictureType::B), 0u);
}

TEST(GopStream, OpenGopsStillStartVariantsAndTheLoopWithoutLeadingBPictures) {
  GopCase c;
  c.openGop = true;
  c.frames = 20;
  const Authored a = author(c);
  expectWellIndexed(a, c);
  const Descriptor& d = a.descriptor;
  bool open = false;
  for (const auto& table : d.index)
    for (const IndexEntry& e : table) open |= e.gopStart && !e.closedGop;
  EXPECT_TRUE(open);
  // Each variant's pictures lie in its own section: its first frame is its first picture in the file.
  for (std::size_t s = 0; s < d.streams.size(); ++s) {
    for (std::uint32_t v = 0; v < d.variants.size(); ++v) {
      const IndexEntry& first = d.index[s][v * d.framesPerVariant];
      for (std::uint32_t f = 0; f < d.framesPerVariant; ++f) {
        const IndexEntry& e = d.index[s][v * d.framesPerVariant + f];
        EXPECT_TRUE(e.sector > first.sector || (e.sector == first.sector && e.offset >= first.offset));
      }
    }
  }
}

TEST(GopStream, IntraOnlyStaysVersion1) {
  GopCase c;
  c.gop = 1;
  c.bFrames = 0;
  const Authored a = author(c);
  EXPECT_TRUE(a.descriptor.intraOnly());
  EXPECT_EQ(serialize(a.descriptor)[1], Descriptor::kVersionIntra);
  const StreamScan scan = scanStream(a.bytes);
  EXPECT_TRUE(scan.errors.empty());
}

TEST(GopStream, BadGopSettingsAreRefusedByName) {
  const auto problem = [](int gop, int b, bool open) {
    EncoderSettings e;
    e.gop = gop;
    e.bFrames = b;
    e.openGop = open;
    return gopProblem(e);
  };
  EXPECT_EQ(problem(1, 0, false), "");
  EXPECT_EQ(problem(12, 2, false), "");
  EXPECT_NE(problem(0, 0, false).find("--gop 0"), std::string::npos);
  EXPECT_NE(problem(4, 4, false).find("--b-frames 4 needs --gop above it"), std::string::npos);
  EXPECT_NE(problem(12, -1, false).find("--b-frames -1"), std::string::npos);
  EXPECT_NE(problem(12, 0, true).find("--open-gop needs --b-frames"), std::string::npos);
  EXPECT_NE(problem(kMaxGop + 1, 0, false).find("outside"), std::string::npos);
  AuthorSettings s;
  s.encoder.gop = 3;
  s.encoder.bFrames = 3;
  StreamWriter w(s);
  Rgba8Image img(16, 16);
  EXPECT_THROW(w.addFrame(img, nullptr), AuthoringError);
}

// A version 2 entry's flags must be a known picture type and known bits.
TEST(GopStream, Version2FlagsAreChecked) {
  GopCase c;
  c.variants = 1;
  c.frames = 8;
  c.loop = 0;
  const Authored a = author(c);
  std::vector<std::uint8_t> body = serialize(a.descriptor);
  const std::size_t entry0 = Descriptor::kHeaderBytes + Descriptor::kStreamBytes * a.descriptor.streams.size() +
                             Descriptor::kVariantBytes * a.descriptor.variants.size();
  body[entry0 + 7] = 0;  // picture type 0
  // Recompute the CRC so the flags check, not the CRC, refuses it.
  for (int i = 0; i < 4; ++i) body[44 + i] = 0;
  const std::uint32_t crc = crc32(body);
  for (int i = 0; i < 4; ++i) body[44 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  const DescriptorParse p = parseDescriptor(body);
  EXPECT_FALSE(p.descriptor);
  EXPECT_NE(p.error.find("flags"), std::string::npos) << p.error;
}

// Every variant ends on a reference (the writer makes it so); a descriptor whose variant ends on a
// B picture could not be decoded lap by lap (ee/decode_order.hpp) and is refused by name.
TEST(GopStream, AVariantEndingOnABPictureIsRefused) {
  GopCase c;
  c.variants = 1;
  c.frames = 8;
  c.loop = 0;
  Descriptor d = author(c).descriptor;
  for (const auto& table : d.index) EXPECT_NE(table.back().type, PictureType::B);
  EXPECT_EQ(d.validate(), "");
  d.index[0].back().type = PictureType::B;
  d.index[0].back().gopStart = false;
  EXPECT_NE(d.validate().find("is a B picture (a variant must end on an I or P picture)"), std::string::npos)
      << d.validate();
}

}  // namespace
}  // namespace vbim::streams
