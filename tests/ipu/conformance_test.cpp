// Conformance: intra streams made by libavcodec over the encoder options the IPU must handle,
// decoded by our decoder and by libavcodec; the Y, Cb and Cr planes are compared.
//
// The bounds we hold for every case (ipu/README.md), per inverse DCT (ipu.idct). The default,
// PCSX2's integer IDCT: against libavcodec with its most accurate inverse DCT (FAAN, floating
// point), at least 98.0 % of samples identical (measured: 98.35 % or better); against libavcodec's
// default integer IDCT, at least 96.0 % (measured: 96.3 % or better). The exact-rounded IDCT: at
// least 99.5 % against FAAN (measured: 99.59 % or better), at least 97.5 % against the default
// (measured: 97.92 % or better). In all, no sample differs by more than 1. The differences are IDCT
// rounding: all are within the IEEE 1180 limits (idct_test.cpp), the exact one 10x inside them.
// Bit-exactness against libmpeg2 is libmpeg2_stream_test.cpp's.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
}

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using testing::Content;
using testing::EncodeOptions;

// Decodes with our decoder and checks that the stream really exercises the option under test.
std::vector<Yuv420Image> decodeOurs(const std::vector<std::uint8_t>& es, const EncodeOptions& o, IdctKind idct) {
  DecoderOptions options;
  options.idct = idct;
  Decoder dec(options);
  std::vector<Yuv420Image> out;
  int fieldDct = 0;
  for (const AccessUnit& au : splitAccessUnits(es)) {
    const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size));
    EXPECT_TRUE(r.clean()) << r.describe();
    if (!r.produced) continue;
    EXPECT_EQ(r.mpeg1, o.mpeg1);
    EXPECT_EQ(r.macroblocksDecoded, r.macroblocks);
    if (!o.mpeg1) {
      EXPECT_EQ(dec.picture().intraVlcFormat, o.intraVlc);
      EXPECT_EQ(dec.picture().alternateScan, o.alternateScan);
      EXPECT_EQ(dec.picture().qScaleType, o.nonLinearQuant);
      EXPECT_EQ(dec.picture().intraDcPrecision, o.dcPrecision);
    }
    fieldDct += r.fieldDctMacroblocks;
    Yuv420Image img;
    copyToYuv420(dec.frame(), dec.width(), dec.height(), img);
    out.push_back(std::move(img));
  }
  if (o.interlacedDct) {
    EXPECT_GT(fieldDct, 0) << "the encoder chose no field DCT: the case tests nothing";
  }
  if (o.customMatrix) {
    EXPECT_NE(dec.sequence().intraMatrix[1], 16);
  }
  return out;
}

struct Bounds {
  IdctKind idct;
  double vsFaan;     // least share of samples identical to libavcodec's FAAN IDCT
  double vsDefault;  // ... to libavcodec's default IDCT
};
constexpr Bounds kBounds[] = {{IdctKind::Pcsx2, 0.980, 0.960}, {IdctKind::Exact, 0.995, 0.975}};

void checkCase(const EncodeOptions& o) {
  SCOPED_TRACE(o.describe());
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  const std::vector<Yuv420Image> faan = testing::decodeWithLibav(es, o.mpeg1, FF_IDCT_FAAN);
  const std::vector<Yuv420Image> simple = testing::decodeWithLibav(es, o.mpeg1, FF_IDCT_AUTO);
  for (const Bounds& bound : kBounds) {
    SCOPED_TRACE(idctKindName(bound.idct));
    const std::vector<Yuv420Image> ours = decodeOurs(es, o, bound.idct);
    ASSERT_EQ(ours.size(), static_cast<std::size_t>(o.frames));
    ASSERT_EQ(faan.size(), ours.size());
    ASSERT_EQ(simple.size(), ours.size());
    for (std::size_t f = 0; f < ours.size(); ++f) {
      ASSERT_EQ(ours[f].width, faan[f].width);
      ASSERT_EQ(ours[f].height, faan[f].height);
      const testing::PlaneDiff a = testing::compare(ours[f], faan[f]);
      const testing::PlaneDiff b = testing::compare(ours[f], simple[f]);
      EXPECT_LE(a.maxAbs, 1) << "frame " << f;
      EXPECT_GE(a.identicalFraction(), bound.vsFaan) << "frame " << f << ": " << a.different << " of " << a.samples;
      EXPECT_LE(b.maxAbs, 1) << "frame " << f;
      EXPECT_GE(b.identicalFraction(), bound.vsDefault) << "frame " << f << ": " << b.different << " of " << b.samples;
      std::printf("%-60s %-5s frame %zu: vs FAAN %zu/%zu differ (max %d), vs default %zu/%zu differ (max %d)\n",
                  o.describe().c_str(), idctKindName(bound.idct), f, a.different, a.samples, a.maxAbs, b.different,
                  b.samples, b.maxAbs);
    }
  }
}

EncodeOptions base(Content c = Content::kBusy) {
  EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = 2;
  o.content = c;
  return o;
}

TEST(IpuConformance, QuantiserRange) {
  for (int q : {1, 2, 3, 5, 8, 12, 17, 24, 31}) {
    EncodeOptions o = base(q < 4 ? Content::kNoise : Content::kBusy);
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuConformance, IntraVlcFormat) {
  for (int q : {1, 4, 16}) {
    EncodeOptions o = base(Content::kNoise);
    o.intraVlc = true;
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuConformance, AlternateScan) {
  EncodeOptions o = base();
  o.alternateScan = true;
  o.quantiser = 3;
  checkCase(o);
}

TEST(IpuConformance, NonLinearQuantiser) {
  for (int q : {1, 9, 28}) {
    EncodeOptions o = base(Content::kNoise);
    o.nonLinearQuant = true;
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuConformance, DcPrecision8To11) {
  for (int p = 0; p <= 3; ++p) {
    EncodeOptions o = base(Content::kSmooth);
    o.dcPrecision = p;
    o.quantiser = 2;
    checkCase(o);
  }
}

TEST(IpuConformance, CustomMatrix) {
  EncodeOptions o = base(Content::kNoise);
  o.customMatrix = true;
  o.quantiser = 4;
  checkCase(o);
}

TEST(IpuConformance, FieldDct) {
  EncodeOptions o = base(Content::kInterlaced);
  o.interlacedDct = true;
  o.quantiser = 3;
  checkCase(o);
}

TEST(IpuConformance, SizesNotMultipleOf16) {
  for (auto [w, h] : {std::pair{17, 9}, std::pair{50, 30}, std::pair{100, 76}}) {
    EncodeOptions o = base(Content::kBusy);
    o.width = w;
    o.height = h;
    o.quantiser = 4;
    checkCase(o);
  }
}

TEST(IpuConformance, Mpeg1Intra) {
  for (int q : {1, 4, 31}) {
    EncodeOptions o = base(q == 1 ? Content::kNoise : Content::kBusy);
    o.mpeg1 = true;
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuConformance, AllOptionsTogether) {
  EncodeOptions o = base(Content::kInterlaced);
  o.intraVlc = o.alternateScan = o.nonLinearQuant = o.customMatrix = o.interlacedDct = true;
  o.dcPrecision = 2;
  o.width = 72;
  o.height = 40;
  o.quantiser = 6;
  checkCase(o);
}

}  // namespace
}  // namespace vbim::ipu
