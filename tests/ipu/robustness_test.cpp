// Bad input: corrupt VLC codes, truncated slices, missing headers and references, broken GOPs,
// absurd sizes and unsupported streams are concealed or refused with a report; the decoder never crashes or loops
// (these run under ASan+UBSan in CI). Also: slice-parallel decode is bit-identical to the serial decode.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/motion_compensation.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/start_code.hpp"
#include "runtime/worker_pool.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

std::vector<std::uint8_t> stream(int frames = 3, bool mpeg1 = false) {
  testing::EncodeOptions o;
  o.width = 80;
  o.height = 48;
  o.frames = frames;
  o.quantiser = 4;
  o.mpeg1 = mpeg1;
  o.content = testing::Content::kBusy;
  return testing::encodeIntra(o);
}

std::span<const std::uint8_t> unit(const std::vector<std::uint8_t>& es, std::size_t i) {
  const AccessUnit au = splitAccessUnits(es).at(i);
  return std::span(es).subspan(au.offset, au.size);
}

bool hasIssue(const PictureReport& r, IssueKind k) {
  return std::any_of(r.issues.begin(), r.issues.end(), [k](const DecodeIssue& i) { return i.kind == k; });
}

// Offset of the first byte of the n-th slice start code's payload.
std::size_t slicePayload(std::span<const std::uint8_t> d, int n) {
  for (std::size_t i = 0; i + 3 < d.size(); ++i)
    if (d[i] == 0 && d[i + 1] == 0 && d[i + 2] == 1 && d[i + 3] >= 1 && d[i + 3] <= 0xAF && n-- == 0) return i + 4;
  return d.size();
}

// A 16x16 intra picture (libavcodec's headers, table B.14) whose one slice is written here: one
// macroblock, intra with a quantiser ('01', scale code 1), a DC size of 0 ('100'), then `codes`
// (each code with its sign, MSB first) and nothing else. Returns the bytes and, through `payload`,
// the offset of the slice's first byte after its start code.
std::vector<std::uint8_t> oneMacroblockPicture(const std::vector<std::pair<std::uint32_t, int>>& codes,
                                               std::size_t& payload, int& headerBits) {
  testing::EncodeOptions o;
  o.width = o.height = 16;
  o.frames = 1;
  std::vector<std::uint8_t> es = testing::encodeIntra(o);
  const std::size_t slice = slicePayload(es, 0);
  es.resize(slice);
  payload = slice;
  std::uint64_t acc = 0;
  int n = 0;
  auto put = [&](std::uint32_t v, int bits) {
    for (int b = bits - 1; b >= 0; --b) {
      acc = acc << 1 | ((v >> b) & 1);
      if (++n == 8) {
        es.push_back(static_cast<std::uint8_t>(acc));
        acc = 0;
        n = 0;
      }
    }
  };
  put(0b00001, 5);  // quantiser_scale_code
  put(0, 1);        // extra_bit_slice
  put(1, 1);        // macroblock_address_increment 1
  put(0b01, 2);     // macroblock_type: intra, quant
  put(0b00001, 5);  // quantiser_scale_code
  put(0b100, 3);    // dct_dc_size_luminance 0
  headerBits = 17;
  for (const auto& [code, bits] : codes) put(code, bits);
  while (n != 0) put(0, 1);
  es.insert(es.end(), {0, 0, 1, 0xB7});  // sequence_end_code
  return es;
}

// Coefficients past the 64th of a block are an error (§7.2.2). The decoder reads short codes two at
// a time; the report names the byte where reading a code at a time finds the error: after the
// code that runs past the block, whether it is the first of the two read together or the second.
// The bit counts are chosen so that the byte after either code differs.
TEST(IpuRobustness, CoefficientsPastTheBlockAreReportedAfterTheirCode) {
  constexpr std::pair<std::uint32_t, int> kRun0 = {0b110, 3};   // '11s' run 0, level 1, positive
  constexpr std::pair<std::uint32_t, int> kRun1 = {0b0110, 4};  // '011s' run 1, level 1, positive
  struct Case {
    const char* name;
    std::vector<std::pair<std::uint32_t, int>> codes;
    int bitsToError;  // after the header and DC: the codes up to the one past the block
    int wrongBits;    // what reading the pair's other code too, or not, would add
  };
  // 64 codes of run 0: the 64th (scan position 64) is the second of a pair read together.
  std::vector<std::pair<std::uint32_t, int>> second(64, kRun0);
  // Run 1 then 61 of run 0 reach position 63 with the 62nd code; the 63rd, past the block, is the
  // first of a pair (with a 64th after it).
  std::vector<std::pair<std::uint32_t, int>> first(1, kRun1);
  first.insert(first.end(), 63, kRun0);
  second.emplace_back(0b10, 2);  // an end of block, for a decoder that took the block as valid
  first.emplace_back(0b10, 2);
  const Case cases[] = {{"second of a pair", second, 64 * 3, -3}, {"first of a pair", first, 4 + 62 * 3, 3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::size_t payload = 0;
    int headerBits = 0;
    const std::vector<std::uint8_t> es = oneMacroblockPicture(c.codes, payload, headerBits);
    const std::size_t at = payload + static_cast<std::size_t>(headerBits + c.bitsToError) / 8;
    // Reading one code too many (or too few) would name another byte.
    ASSERT_NE(at, payload + static_cast<std::size_t>(headerBits + c.bitsToError + c.wrongBits) / 8);
    Decoder dec;
    const PictureReport r = dec.decode(es);
    ASSERT_TRUE(r.produced) << r.describe();
    ASSERT_FALSE(r.issues.empty()) << r.describe();  // then the blocks not covered
    EXPECT_EQ(r.issues[0].kind, IssueKind::kCoefficientOverrun) << r.describe();
    EXPECT_EQ(r.issues[0].byteOffset, at) << r.describe();
    EXPECT_EQ(r.issues[0].mbX, 0);
    EXPECT_EQ(r.issues[0].mbY, 0);
    EXPECT_EQ(r.macroblocksConcealed, 1);
  }
}

// The same macroblock with 63 coefficients and its end of block is clean: the error above is the
// 64th.
TEST(IpuRobustness, SixtyThreeCoefficientsFillABlock) {
  std::size_t payload = 0;
  int headerBits = 0;
  std::vector<std::pair<std::uint32_t, int>> codes(63, {0b110, 3});
  codes.emplace_back(0b10, 2);  // the end of block of block 0
  // Blocks 1-5: DC size 0 (luma '100', chroma '00') and an end of block each.
  for (int b = 1; b < 6; ++b) {
    codes.emplace_back(b < 4 ? 0b100 : 0b00, b < 4 ? 3 : 2);
    codes.emplace_back(0b10, 2);
  }
  std::vector<std::uint8_t> es = oneMacroblockPicture(codes, payload, headerBits);
  Decoder dec;
  const PictureReport r = dec.decode(es);
  ASSERT_TRUE(r.produced) << r.describe();
  EXPECT_TRUE(r.clean()) << r.describe();
}

TEST(IpuRobustness, CleanStreamHasNoIssues) {
  const auto es = stream();
  Decoder dec;
  for (std::size_t i = 0; i < 3; ++i) {
    const PictureReport r = dec.decode(unit(es, i));
    EXPECT_TRUE(r.produced);
    EXPECT_TRUE(r.clean()) << r.describe();
    EXPECT_EQ(r.macroblocks, 15);
    EXPECT_EQ(r.macroblocksConcealed, 0);
  }
}

TEST(IpuRobustness, CorruptFirstPictureIsConcealedMidGrey) {
  auto es = stream(1);
  std::vector<std::uint8_t> bad(es.begin(), es.end());
  const std::size_t p = slicePayload(bad, 0);
  // Overwrite the first slice's macroblock data (after the 5-bit quantiser code) with zeros
  // followed by ones: no valid macroblock_address_increment starts with eleven zeros.
  bad[p] &= 0xF8;
  bad[p + 1] = 0x00;
  bad[p + 2] = 0x00;
  Decoder dec;
  const PictureReport r = dec.decode(bad);
  ASSERT_TRUE(r.produced);
  EXPECT_FALSE(r.clean());
  EXPECT_EQ(r.macroblocksConcealed, 5);  // the whole first row (80 px = 5 macroblocks)
  EXPECT_TRUE(hasIssue(r, IssueKind::kMissingMacroblocks));
  const FrameStore& fs = dec.frame();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 80; ++x) ASSERT_EQ(fs.y[static_cast<std::size_t>(y) * fs.lumaStride + x], 128);
  EXPECT_EQ(fs.cb[0], 128);
  EXPECT_EQ(fs.cr[0], 128);
  // The issue names a place: the byte offset inside the bytes we gave, and the macroblock.
  ASSERT_FALSE(r.issues.empty());
  EXPECT_GE(r.issues[0].byteOffset, p);
  EXPECT_LT(r.issues[0].byteOffset, p + 8);
  EXPECT_EQ(r.issues[0].mbY, 0);
}

TEST(IpuRobustness, ConcealedMacroblocksKeepThePreviousPicture) {
  const auto es = stream(2);
  Decoder ref;
  ref.decode(unit(es, 0));
  const std::vector<std::uint8_t> first = ref.frame().y;
  std::vector<std::uint8_t> second(unit(es, 1).begin(), unit(es, 1).end());
  // Cut the second picture's second slice short: its tail must keep picture 0's pixels.
  const std::size_t p = slicePayload(second, 1);
  std::fill(second.begin() + static_cast<std::ptrdiff_t>(p) + 6, second.begin() + static_cast<std::ptrdiff_t>(p) + 40,
            0xFF);
  Decoder dec;
  dec.decode(unit(es, 0));
  const PictureReport r = dec.decode(second);
  ASSERT_TRUE(r.produced);
  EXPECT_GT(r.macroblocksConcealed, 0);
  Decoder clean;
  clean.decode(unit(es, 0));
  clean.decode(unit(es, 1));
  // Row 1 (luma lines 16..31): concealed macroblocks equal picture 0, decoded ones picture 1.
  int kept = 0;
  for (int mb = 0; mb < 5; ++mb) {
    bool same = true;
    for (int y = 16; y < 32; ++y)
      for (int x = mb * 16; x < mb * 16 + 16; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * dec.frame().lumaStride + x;
        same = same && dec.frame().y[i] == first[i];
      }
    kept += same;
  }
  EXPECT_EQ(kept, r.macroblocksConcealed);
  // Row 0 and row 2 decode normally.
  for (int y : {0, 40})
    for (int x = 0; x < 80; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * dec.frame().lumaStride + x;
      EXPECT_EQ(dec.frame().y[i], clean.frame().y[i]);
    }
}

TEST(IpuRobustness, EveryTruncationIsSafe) {
  const auto es = stream(2);
  const auto pic = unit(es, 0);
  for (std::size_t n = 0; n <= pic.size(); n += 7) {
    Decoder dec;
    const PictureReport r = dec.decode(pic.subspan(0, n));
    if (r.produced) {
      EXPECT_LE(r.macroblocksDecoded, r.macroblocks);
    }
  }
}

// Decodes `trials` copies of the stream, each with 1 to maxFlips random bits flipped at or after
// byte `from`; every picture's macroblocks must be decoded or concealed. Returns the pictures that
// reported issues.
int decodeWithBitFlips(const std::vector<std::uint8_t>& es, std::size_t from, int trials, int maxFlips,
                       std::uint32_t seed) {
  std::uint32_t s = seed;
  int withIssues = 0;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<std::uint8_t> bad = es;
    for (int k = 0; k < 1 + trial % maxFlips; ++k) {
      s = s * 1664525u + 1013904223u;
      const std::size_t pos = from + (s >> 8) % (bad.size() - from);
      bad[pos] ^= static_cast<std::uint8_t>(1u << (s & 7));
    }
    Decoder dec;
    for (const AccessUnit& au : splitAccessUnits(bad)) {
      const PictureReport r = dec.decode(std::span(bad).subspan(au.offset, au.size));
      EXPECT_EQ(r.macroblocksDecoded + r.macroblocksConcealed, r.macroblocks);
      withIssues += r.issueCount > 0;
    }
  }
  return withIssues;
}

TEST(IpuRobustness, RandomBitFlipsAreConcealedAndReported) {
  EXPECT_GT(decodeWithBitFlips(stream(3), 20, 300, 5, 12345), 100);
}

// Zero stuffing before start codes is allowed (ISO/IEC 13818-2 §5.3, next_start_code()); every
// amount moves the start codes to every alignment of the decoder's word-wise start-code search.
TEST(IpuRobustness, ZeroStuffingBeforeStartCodesChangesNothing) {
  const auto es = stream(1);
  Decoder clean;
  ASSERT_TRUE(clean.decode(es).clean());
  for (int stuffing = 1; stuffing <= 16; ++stuffing) {
    std::vector<std::uint8_t> padded;
    for (std::size_t i = 0; i < es.size(); ++i) {
      if (i > 0 && i + 2 < es.size() && es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1)
        padded.insert(padded.end(), static_cast<std::size_t>(stuffing), 0);
      padded.push_back(es[i]);
    }
    Decoder dec;
    const PictureReport r = dec.decode(padded);
    EXPECT_TRUE(r.clean()) << "stuffing " << stuffing << ": " << r.describe();
    EXPECT_EQ(r.macroblocksDecoded, 15);
    EXPECT_EQ(dec.frame().y, clean.frame().y) << "stuffing " << stuffing;
    EXPECT_EQ(dec.frame().cb, clean.frame().cb) << "stuffing " << stuffing;
  }
}

// A sequence extension among a picture's slices whose size extension bits make the sequence 4096
// pixels wider (found by the fuzzer): the picture was decoded into a 2-macroblock-wide store, so
// width() and the RGBA output keep the size it was decoded at; cropping the store to the new
// sequence size read far past its end.
TEST(IpuRobustness, SizeChangedInsideAPictureDoesNotOutgrowTheStore) {
  testing::EncodeOptions o;
  o.width = 32;
  o.height = 32;
  o.frames = 1;
  o.content = testing::Content::kPattern;
  const auto es = testing::encodeIntra(o);
  const std::size_t ext = findStartCode(es.data(), es.size(), 4);
  ASSERT_EQ(es[ext + 3], 0xB5);
  ASSERT_EQ(es[ext + 4] >> 4, 1) << "sequence extension expected after the sequence header";
  std::vector<std::uint8_t> wider(es.begin() + static_cast<std::ptrdiff_t>(ext),
                                  es.begin() + static_cast<std::ptrdiff_t>(ext + 10));
  wider[6] |= 0x80;  // horizontal_size_extension = 01: width + 4096
  std::vector<std::uint8_t> bytes = es;
  const std::size_t secondSlice = slicePayload(bytes, 1) - 4;
  ASSERT_LT(secondSlice, bytes.size());
  bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(secondSlice), wider.begin(), wider.end());
  for (const bool parallel : {false, true}) {
    SCOPED_TRACE(parallel ? "on a pool" : "serial");
    Decoder dec;
    WorkerPool pool(1);
    Rgba8Image rgba;
    const PictureReport r = parallel ? decodeToRgba(dec, bytes, rgba, pool) : decodeToRgba(dec, bytes, rgba);
    ASSERT_TRUE(r.produced);
    EXPECT_EQ(dec.sequence().width, 32 + 4096);
    EXPECT_EQ(dec.width(), 32);
    EXPECT_EQ(dec.height(), 32);
    EXPECT_EQ(rgba.width, 32);
    Rgba8Image reference;
    convertToRgba32(dec.frame(), dec.width(), dec.height(), {}, reference);
    EXPECT_EQ(rgba.pixels, reference.pixels);
  }
}

TEST(IpuRobustness, MissingSequenceHeaderIsUndecodable) {
  const auto es = stream(1);
  std::vector<std::uint8_t> bad;
  // Drop everything before the picture start code (sequence header, extensions, GOP).
  for (std::size_t i = 0; i + 3 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0) {
      bad.assign(es.begin() + static_cast<std::ptrdiff_t>(i), es.end());
      break;
    }
  Decoder dec;
  const PictureReport r = dec.decode(bad);
  EXPECT_FALSE(r.produced);
  EXPECT_TRUE(r.undecodable);
  EXPECT_TRUE(hasIssue(r, IssueKind::kMissingSequenceHeader));
  const PictureReport noPicture = dec.decode(std::span(bad).subspan(slicePayload(bad, 0) - 4));
  EXPECT_TRUE(hasIssue(noPicture, IssueKind::kMissingPictureHeader));
}

// Patches the sequence extension's chroma_format (bits 13..14 after the extension start code).
TEST(IpuRobustness, Chroma422IsUndecodable) {
  auto es = stream(1);
  for (std::size_t i = 0; i + 6 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0xB5 && (es[i + 4] >> 4) == 1) {
      // byte i+5 bits: [profile low 4][progressive][chroma 2][h ext hi]
      es[i + 5] = static_cast<std::uint8_t>((es[i + 5] & ~0x06) | (2 << 1));
      break;
    }
  Decoder dec;
  const PictureReport r = dec.decode(es);
  EXPECT_TRUE(r.undecodable);
  EXPECT_TRUE(hasIssue(r, IssueKind::kUnsupportedChromaFormat));
}

// A GOP of I, P and B pictures with real motion (issue #29).
std::vector<std::uint8_t> gopStream(int frames, int bFrames, bool interlaced = false) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = frames;
  o.gopSize = 6;
  o.bFrames = bFrames;
  o.quantiser = 4;
  o.interlacedDct = interlaced;
  o.interlacedMe = interlaced;
  o.content = testing::Content::kPan;
  return testing::encodeIntra(o);
}

TEST(IpuRobustness, PredictedPicturesDecode) {
  const auto es = gopStream(7, 2);
  Decoder dec;
  int types[4] = {};
  for (const AccessUnit& au : splitAccessUnits(es)) {
    const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size));
    EXPECT_TRUE(r.produced);
    EXPECT_TRUE(r.clean()) << r.describe();
    EXPECT_EQ(r.macroblocksDecoded, r.macroblocks);
    ++types[r.pictureCodingType & 3];
  }
  EXPECT_EQ(types[1], 2);  // I P B B P B B with a GOP of 6: I B B P B B I ... in decode order I P B B I B
  EXPECT_GT(types[2], 0);
  EXPECT_GT(types[3], 0);
}

// A P or B picture whose reference frame never arrived (a stream cut after its I picture, a
// broken GOP) is predicted from mid-grey, reported once, and its macroblocks count as concealed.
// The sequence header and what follows it up to the first picture's header.
std::vector<std::uint8_t> headersBeforeFirstPicture(const std::vector<std::uint8_t>& es) {
  for (std::size_t i = 0; i + 3 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0) return {es.begin(), es.begin() + i};
  return es;
}

TEST(IpuRobustness, MissingReferenceIsConcealedAndReported) {
  const auto es = gopStream(4, 0);  // I P P P
  Decoder dec;
  dec.decode(headersBeforeFirstPicture(es));
  const PictureReport r = dec.decode(unit(es, 1));
  EXPECT_EQ(r.pictureCodingType, 2);
  EXPECT_TRUE(r.produced);
  EXPECT_FALSE(r.undecodable);
  EXPECT_TRUE(hasIssue(r, IssueKind::kMissingReference));
  EXPECT_EQ(r.macroblocksConcealed, r.macroblocks);
  EXPECT_EQ(r.macroblocksDecoded + r.macroblocksConcealed, r.macroblocks);
  // The next P picture has its reference (the concealed one): no new issue.
  const PictureReport next = dec.decode(unit(es, 2));
  EXPECT_TRUE(next.clean()) << next.describe();
  // B pictures without their references.
  const auto withB = gopStream(4, 2);  // decode order I P B B
  Decoder fresh;
  fresh.decode(headersBeforeFirstPicture(withB));
  const PictureReport b = fresh.decode(unit(withB, 2));
  EXPECT_EQ(b.pictureCodingType, 3);
  EXPECT_TRUE(hasIssue(b, IssueKind::kMissingReference));
  EXPECT_FALSE(fresh.flushDisplay());  // a B frame is shown at once and is not kept
}

// Pictures dropped anywhere (a broken GOP), P and B slices cut anywhere, and random bit flips in
// P and B pictures: concealed and counted, never a crash (ASan, UBSan in CI).
TEST(IpuRobustness, BrokenGopsAndDamagedPredictedPicturesAreSafe) {
  for (const bool interlaced : {false, true}) {
    const auto es = gopStream(7, 2, interlaced);
    const auto units = splitAccessUnits(es);
    for (std::size_t drop = 0; drop < units.size(); ++drop) {
      Decoder dec;
      for (std::size_t i = 0; i < units.size(); ++i) {
        if (i == drop) continue;
        const PictureReport r = dec.decode(std::span(es).subspan(units[i].offset, units[i].size));
        EXPECT_EQ(r.macroblocksDecoded + r.macroblocksConcealed, r.macroblocks);
      }
      while (dec.flushDisplay()) {
      }
    }
    const auto p = unit(es, 1);
    for (std::size_t n = 0; n <= p.size(); n += 5) {
      Decoder dec;
      dec.decode(unit(es, 0));
      const PictureReport r = dec.decode(p.subspan(0, n));
      if (r.produced) {
        EXPECT_EQ(r.macroblocksDecoded + r.macroblocksConcealed, r.macroblocks);
      }
    }
    // Bits flipped in the P and B pictures (the I picture stays clean).
    EXPECT_GT(decodeWithBitFlips(es, units[1].offset, 150, 4, 777), 40);
  }
}

// A vector far outside the picture is moved to the reference's edge and reported; nothing outside
// the reference frame is read (ASan).
TEST(IpuRobustness, OutOfRangeVectorIsClamped) {
  FrameStore ref;
  ref.reset(2, 2);
  for (std::size_t i = 0; i < ref.y.size(); ++i) ref.y[i] = static_cast<std::uint8_t>(i);
  FrameStore cur;
  cur.reset(2, 2);
  PictureParams pp;
  pp.mbWidth = 2;
  pp.mbRows = 2;
  pp.y = cur.y.data();
  pp.cb = cur.cb.data();
  pp.cr = cur.cr.data();
  pp.yStride = cur.lumaStride;
  pp.cStride = cur.chromaStride;
  Macroblock mb;
  mb.mbX = 1;
  mb.mbY = 1;
  mb.opCount = 1;
  const int cases[][3] = {{4001, -4001, 1}, {-4001, 4001, 1}, {-3, -5, 0}, {0, 0, 0}, {1, 0, 1}};
  for (const auto& c : cases) {
    mb.ops[0].mvx = static_cast<std::int16_t>(c[0]);
    mb.ops[0].mvy = static_cast<std::int16_t>(c[1]);
    const PredictionResult r = predictMacroblock(mb, ReferenceSet{&ref, nullptr, &cur}, pp);
    EXPECT_EQ(r.clamped, c[2] != 0) << c[0] << "," << c[1];
    EXPECT_FALSE(r.missingReference);
  }
  mb.ops[0].ref = PredictionRef::kBackward;
  EXPECT_TRUE(predictMacroblock(mb, ReferenceSet{&ref, nullptr, &cur}, pp).missingReference);
}

TEST(IpuRobustness, AbsurdSizeIsRefused) {
  auto es = stream(1);
  ASSERT_EQ(es[3], 0xB3);
  DecoderOptions opt;
  opt.maxWidth = 64;  // the stream is 80 wide
  Decoder dec(opt);
  const PictureReport r = dec.decode(es);
  EXPECT_TRUE(r.undecodable);
  EXPECT_TRUE(hasIssue(r, IssueKind::kAbsurdSize));
  es[4] = es[5] = 0;
  es[6] &= 0x0F;  // horizontal_size = 0, vertical_size = 48 & 0xFF...
  Decoder dec2;
  EXPECT_TRUE(dec2.decode(es).undecodable);
}

// The start-code scan against its definition on buffers dense with near misses (00 01, 00 00 00,
// 00 00 at the end), from every start offset, at every length up to 300 bytes.
TEST(IpuRobustness, StartCodeScanFindsTheFirstPrefix) {
  auto naive = [](const std::vector<std::uint8_t>& d, std::size_t from) {
    for (std::size_t i = from; i + 2 < d.size(); ++i)
      if (d[i] == 0 && d[i + 1] == 0 && d[i + 2] == 1) return i;
    return d.size();
  };
  std::uint32_t state = 11;
  auto below = [&](std::uint32_t n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
  };
  for (int t = 0; t < 600; ++t) {
    std::vector<std::uint8_t> d(below(300));
    const std::uint32_t density = 2 + below(40);  // 1 in `density` bytes is 00, as many 01
    for (auto& b : d) {
      const std::uint32_t r = below(2 * density);
      b = static_cast<std::uint8_t>(r == 0 ? 0 : (r == 1 ? 1 : 2 + below(254)));
    }
    for (std::size_t from = 0; from <= d.size() + 1; ++from)
      ASSERT_EQ(findStartCode(d.data(), d.size(), from), from <= d.size() ? naive(d, from) : d.size())
          << t << " " << from;
  }
}

// A slice for a row that was already decoded, after the later rows (here picture 2's first row
// appended to picture 1): the serial decode lets it overwrite that row; the parallel one, which
// groups slices into whole rows, must keep that order and give the same bytes.
TEST(IpuRobustness, ARowRevisitedLateOverwritesAsInTheSerialDecode) {
  testing::EncodeOptions o;
  o.width = 160;
  o.height = 144;
  o.frames = 2;
  o.quantiser = 3;
  o.content = testing::Content::kNoise;
  const auto es = testing::encodeIntra(o);
  const auto units = splitAccessUnits(es);
  ASSERT_EQ(units.size(), 2u);
  const auto second = std::span(es).subspan(units[1].offset, units[1].size);
  const std::size_t sliceAt = findStartCode(second.data(), second.size(), 0);
  std::size_t first = sliceAt;
  while (first < second.size() && second[first + 3] != 0x01)
    first = findStartCode(second.data(), second.size(), first + 3);
  ASSERT_LT(first, second.size()) << "no slice of row 0 in picture 2";
  const std::size_t end = findStartCode(second.data(), second.size(), first + 3);
  std::vector<std::uint8_t> picture(es.begin() + static_cast<std::ptrdiff_t>(units[0].offset),
                                    es.begin() + static_cast<std::ptrdiff_t>(units[0].offset + units[0].size));
  picture.insert(picture.end(), second.begin() + static_cast<std::ptrdiff_t>(first),
                 second.begin() + static_cast<std::ptrdiff_t>(end));
  Decoder serial, parallel, plain;
  WorkerPool pool(1);
  const PictureReport a = serial.decode(picture);
  const PictureReport b = parallel.decode(picture, pool);
  plain.decode(std::span(es).subspan(units[0].offset, units[0].size));
  EXPECT_EQ(a.issueCount, b.issueCount);
  EXPECT_EQ(serial.frame().y, parallel.frame().y);
  EXPECT_EQ(serial.frame().cb, parallel.frame().cb);
  EXPECT_EQ(serial.frame().cr, parallel.frame().cr);
  EXPECT_NE(serial.frame().y, plain.frame().y) << "the appended slice should have changed row 0";
}

TEST(IpuRobustness, SliceParallelDecodeIsBitIdentical) {
  testing::EncodeOptions o;
  o.width = 160;
  o.height = 144;
  o.frames = 2;
  o.quantiser = 2;
  o.content = testing::Content::kNoise;
  auto es = testing::encodeIntra(o);
  WorkerPool pool(1);
  WorkerPool sleepy(3, std::chrono::microseconds(0));  // more threads than jobs of some pictures
  for (int corrupt = 0; corrupt < 2; ++corrupt) {
    if (corrupt) {
      for (std::size_t i = 200; i < es.size(); i += 997) es[i] ^= 0x10;
    }
    Decoder serial, parallel, threeThreads;
    for (const AccessUnit& au : splitAccessUnits(es)) {
      const auto bytes = std::span(es).subspan(au.offset, au.size);
      const PictureReport a = serial.decode(bytes);
      const PictureReport b = parallel.decode(bytes, pool);
      const PictureReport c = threeThreads.decode(bytes, sleepy);
      for (const auto& [r, d] : {std::pair{&b, &parallel}, std::pair{&c, &threeThreads}}) {
        EXPECT_EQ(a.issueCount, r->issueCount);
        EXPECT_EQ(a.macroblocksConcealed, r->macroblocksConcealed);
        EXPECT_EQ(serial.frame().y, d->frame().y);
        EXPECT_EQ(serial.frame().cb, d->frame().cb);
        EXPECT_EQ(serial.frame().cr, d->frame().cr);
      }
    }
  }
}

TEST(IpuRobustness, Mpeg1CorruptionIsSafe) {
  auto es = stream(2, true);
  for (std::size_t i = 60; i < es.size(); i += 101) es[i] = static_cast<std::uint8_t>(es[i] * 7 + 3);
  Decoder dec;
  for (const AccessUnit& au : splitAccessUnits(es)) dec.decode(std::span(es).subspan(au.offset, au.size));
  SUCCEED();
}

TEST(IpuRobustness, ElementaryStreamSplitsIntoPictures) {
  const auto es = stream(4);
  const auto units = splitAccessUnits(es);
  ASSERT_EQ(units.size(), 4u);
  std::size_t total = 0;
  for (const AccessUnit& u : units) {
    EXPECT_EQ(u.offset, total);
    total += u.size;
    // Each unit starts with the sequence header libavcodec repeats for every intra GOP.
    EXPECT_EQ(es[u.offset + 3], 0xB3);
  }
  EXPECT_EQ(total, es.size());
}

}  // namespace
}  // namespace vbim::ipu

namespace vbim::ipu {
namespace {

// The IPU's IDP field cannot express 11-bit DC precision; PCSX2 decodes such streams as 9-bit.
// The option reproduces that (the picture comes out wrong, as it would there); by default the
// standard's 11 bits are used.
TEST(IpuRobustness, DcPrecision11CanBeTreatedAsNineLikePcsx2) {
  testing::EncodeOptions o;
  o.width = 48;
  o.height = 32;
  o.frames = 1;
  o.dcPrecision = 3;
  o.quantiser = 2;
  const auto es = testing::encodeIntra(o);
  Decoder standard;
  DecoderOptions pcsx2;
  pcsx2.dcPrecision11AsNine = true;
  Decoder nine(pcsx2);
  EXPECT_TRUE(standard.decode(es).clean());
  EXPECT_TRUE(nine.decode(es).produced);
  EXPECT_EQ(standard.picture().intraDcPrecision, 3);
  EXPECT_NE(standard.frame().y, nine.frame().y);
}

}  // namespace
}  // namespace vbim::ipu

namespace vbim::ipu {
namespace {

// A field picture (picture_structure = top field) decodes into every other line of the frame
// store; libavcodec's encoder writes frame pictures only, so the structure is patched in. Its
// second macroblock row lies outside a field of this height and is reported.
TEST(IpuRobustness, TopFieldPictureWritesEvenLinesOnly) {
  testing::EncodeOptions o;
  o.width = 32;
  o.height = 32;
  o.frames = 1;
  o.content = testing::Content::kPattern;
  auto es = testing::encodeIntra(o);
  bool patched = false;
  for (std::size_t i = 0; i + 7 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0xB5 && (es[i + 4] >> 4) == 8) {
      es[i + 6] = static_cast<std::uint8_t>((es[i + 6] & ~0x03) | 0x01);  // picture_structure = 1
      patched = true;
      break;
    }
  ASSERT_TRUE(patched);
  Decoder dec;
  const PictureReport r = dec.decode(es);
  ASSERT_TRUE(r.produced);
  EXPECT_EQ(dec.picture().pictureStructure, 1);
  EXPECT_EQ(r.macroblocks, 2);  // one field row of two macroblocks
  EXPECT_EQ(r.macroblocksDecoded, 2);
  EXPECT_TRUE(hasIssue(r, IssueKind::kBadSlicePosition));
  const FrameStore& fs = dec.frame();
  int evenChanged = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const std::uint8_t v = fs.y[static_cast<std::size_t>(y) * fs.lumaStride + x];
      if (y & 1) {
        ASSERT_EQ(v, 128) << "odd line " << y << " belongs to the bottom field";
      } else {
        evenChanged += v != 128;
      }
    }
  EXPECT_GT(evenChanged, 100);
}

}  // namespace
}  // namespace vbim::ipu
