// Whole MPEG-1 and MPEG-2 MP@ML (issue #29): streams with GOPs, P and B pictures, made by
// libavcodec at test time, decoded by us (display order, libmpeg2's IDCT) and by libmpeg2 0.5.1's C
// decoder (acceleration off, as `mpeg2dec -c`): every sample of every picture must be identical,
// with our scalar and our Highway kernels.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "tests/ipu/support/field_picture_writer.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"
#include "tests/ipu/support/libmpeg2_decode.hpp"

namespace vbim::ipu {
namespace {

struct OurDecode {
  std::vector<Yuv420Image> frames;
  std::size_t issues = 0;
  int predicted = 0;  // P and B pictures
  std::string firstIssues;
};

OurDecode decodeOurs(const std::vector<std::uint8_t>& es, SliceRunner* runner = nullptr,
                     const Kernels* kernels = nullptr) {
  DecoderOptions options;
  options.idct = IdctKind::Libmpeg2;
  options.kernels = kernels;
  Decoder dec(options);
  OurDecode out;
  auto take = [&]() {
    Yuv420Image img(dec.displayWidth(), dec.displayHeight());
    copyToYuv420(*dec.displayFrame(), dec.displayWidth(), dec.displayHeight(), img);
    out.frames.push_back(std::move(img));
  };
  for (const AccessUnit& au : splitAccessUnits(es)) {
    const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size), runner);
    out.issues += r.issueCount;
    if (out.firstIssues.empty()) out.firstIssues = r.describe();
    if (r.pictureCodingType == 2 || r.pictureCodingType == 3) ++out.predicted;
    if (dec.displayFrame()) take();
  }
  while (dec.flushDisplay()) take();
  return out;
}

void expectIdentical(const testing::EncodeOptions& o) {
  SCOPED_TRACE(o.describe());
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  const std::vector<Yuv420Image> ref = testing::decodeWithLibmpeg2(es);
  // The scalar reference kernels (IDCT, motion compensation), then the Highway ones.
  for (const Kernels* k : {&scalarKernels(), &simdKernels()}) {
    SCOPED_TRACE(k->name);
    const OurDecode ours = decodeOurs(es, nullptr, k);
    EXPECT_EQ(ours.issues, 0u) << ours.firstIssues;
    ASSERT_EQ(ours.frames.size(), ref.size());
    ASSERT_EQ(ref.size(), static_cast<std::size_t>(o.frames));
    if (o.gopSize > 1) {
      EXPECT_GT(ours.predicted, 0);
    }
    for (std::size_t f = 0; f < ref.size(); ++f) {
      const testing::PlaneDiff d = testing::compare(ours.frames[f], ref[f]);
      EXPECT_EQ(d.samples, ref[f].y.size() + ref[f].cb.size() + ref[f].cr.size());
      EXPECT_EQ(d.different, 0u) << "display frame " << f << ": max difference " << d.maxAbs;
    }
  }
}

testing::EncodeOptions gop(int w, int h, int frames, int gopSize, int bFrames, testing::Content content, int q) {
  testing::EncodeOptions o;
  o.width = w;
  o.height = h;
  o.frames = frames;
  o.gopSize = gopSize;
  o.bFrames = bFrames;
  o.content = content;
  o.quantiser = q;
  return o;
}

TEST(IpuGop, ProgressiveGop12TwoBPictures) {
  expectIdentical(gop(352, 288, 8, 12, 2, testing::Content::kPan, 4));
  expectIdentical(gop(256, 256, 7, 12, 2, testing::Content::kNoise, 6));
}

TEST(IpuGop, Gop6AndPOnly) {
  expectIdentical(gop(256, 256, 8, 6, 2, testing::Content::kPattern, 3));
  expectIdentical(gop(352, 288, 6, 12, 0, testing::Content::kPan, 2));
}

TEST(IpuGop, AlternateScanNonLinearQuantiser) {
  testing::EncodeOptions o = gop(720, 480, 5, 12, 2, testing::Content::kPan, 5);
  o.alternateScan = true;
  o.nonLinearQuant = true;
  expectIdentical(o);
}

TEST(IpuGop, Mpeg1) {
  testing::EncodeOptions o = gop(352, 288, 8, 12, 2, testing::Content::kPan, 4);
  o.mpeg1 = true;
  expectIdentical(o);
  o = gop(256, 256, 6, 6, 1, testing::Content::kNoise, 8);
  o.mpeg1 = true;
  expectIdentical(o);
}

TEST(IpuGop, InterlacedFieldPredictionAndFieldDct) {
  testing::EncodeOptions o = gop(720, 576, 5, 12, 2, testing::Content::kPan, 4);
  o.interlacedDct = true;
  o.interlacedMe = true;
  expectIdentical(o);
  o = gop(352, 288, 7, 6, 2, testing::Content::kInterlaced, 3);
  o.interlacedDct = true;
  o.interlacedMe = true;
  o.alternateScan = true;
  expectIdentical(o);
}

TEST(IpuGop, LargeStillPicture) {
  expectIdentical(gop(1024, 1024, 4, 12, 2, testing::Content::kLightmap, 3));
}

// What libavcodec never writes: field pictures (the second field of a P frame predicting from the
// first, §7.6.3.5), 16x8 prediction, dual prime in field and frame pictures, skips in field
// pictures; written by tests/ipu/support/field_picture_writer.* after a libavcodec I frame.
void expectFieldStreamIdentical(const testing::FieldStreamOptions& o) {
  SCOPED_TRACE(std::string(o.fieldPictures ? "field" : "frame") + " pictures, dual prime " +
               (o.dualPrime ? "on" : "off") + (o.concealmentVectors ? ", concealment vectors" : "") + ", seed " +
               std::to_string(o.seed));
  const std::vector<std::uint8_t> es = testing::makeFieldStream(o);
  const std::vector<Yuv420Image> ref = testing::decodeWithLibmpeg2(es);
  const OurDecode ours = decodeOurs(es);
  EXPECT_EQ(ours.issues, 0u) << ours.firstIssues;
  ASSERT_EQ(ref.size(), static_cast<std::size_t>(1 + o.pictures));
  ASSERT_EQ(ours.frames.size(), ref.size());
  for (std::size_t f = 0; f < ref.size(); ++f) {
    const testing::PlaneDiff d = testing::compare(ours.frames[f], ref[f]);
    EXPECT_EQ(d.different, 0u) << "display frame " << f << ": max difference " << d.maxAbs;
  }
}

TEST(IpuGop, FieldPicturesAndDualPrime) {
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    testing::FieldStreamOptions o;
    o.seed = seed;
    o.pictures = 3;
    expectFieldStreamIdentical(o);  // P field pairs with field, 16x8 and dual-prime prediction
    o.dualPrime = false;
    expectFieldStreamIdentical(o);
    o.fieldPictures = false;  // P frame pictures: field prediction and field DCT
    expectFieldStreamIdentical(o);
    o.dualPrime = true;  // and dual prime
    o.width = 128;
    o.height = 96;
    expectFieldStreamIdentical(o);
    o.concealmentVectors = true;  // intra macroblocks in P pictures, with concealment vectors
    expectFieldStreamIdentical(o);
    o.fieldPictures = true;
    expectFieldStreamIdentical(o);
  }
}

// A stream that ends after the first field of a P frame: the I frame and the half-decoded P frame
// both leave (the second field's lines keep the reference's samples), none twice.
TEST(IpuGop, LoneLastFieldStillLeaves) {
  testing::FieldStreamOptions o;
  o.pictures = 1;
  std::vector<std::uint8_t> es = testing::makeFieldStream(o);
  std::size_t lastPicture = 0;
  for (std::size_t i = 0; i + 3 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0) lastPicture = i;
  es.resize(lastPicture);  // drop the bottom field
  const OurDecode ours = decodeOurs(es);
  EXPECT_EQ(ours.frames.size(), 2u);
  EXPECT_GE(ours.predicted, 1);
}

// Slice-parallel decode of P and B pictures gives the same bytes.
TEST(IpuGop, SliceParallelIsIdentical) {
  struct TwoThreads : SliceRunner {
    unsigned threads() const override { return 1; }
    void run(std::size_t count, const std::function<void(std::size_t)>& fn) override {
      // Odd jobs first, then even ones: any order must give the same frame.
      for (std::size_t k = 1; k < count; k += 2) fn(k);
      for (std::size_t k = 0; k < count; k += 2) fn(k);
    }
  } runner;
  testing::EncodeOptions o = gop(352, 288, 7, 6, 2, testing::Content::kPan, 4);
  o.interlacedDct = true;
  o.interlacedMe = true;
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  const OurDecode serial = decodeOurs(es);
  const OurDecode parallel = decodeOurs(es, &runner);
  ASSERT_EQ(serial.frames.size(), parallel.frames.size());
  for (std::size_t f = 0; f < serial.frames.size(); ++f) {
    EXPECT_EQ(serial.frames[f].y, parallel.frames[f].y);
    EXPECT_EQ(serial.frames[f].cb, parallel.frames[f].cb);
    EXPECT_EQ(serial.frames[f].cr, parallel.frames[f].cr);
  }
}

}  // namespace
}  // namespace vbim::ipu
