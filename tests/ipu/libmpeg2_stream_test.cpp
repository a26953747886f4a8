// Whole streams against libmpeg2: intra streams made at test time by libavcodec (MPEG-1 and MPEG-2,
// 256x256 and up, field DCT, alternate scan, non-linear quantiser, intra VLC), decoded by our
// decoder with IdctKind::Libmpeg2 and by Debian's libmpeg2 with acceleration off (its C IDCT, what
// `mpeg2dec -c` computes): every sample of every picture must be identical. The other kinds are
// measured against it (the figures of docs/timing/ipu.md#idct).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

extern "C" {
#include <mpeg2.h>
}

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using testing::Content;
using testing::EncodeOptions;

std::vector<Yuv420Image> decodeWithLibmpeg2(const std::vector<std::uint8_t>& es) {
  static const bool plainC = mpeg2_accel(0) == 0;  // before the first mpeg2_init(): the C IDCT
  EXPECT_TRUE(plainC) << "libmpeg2 picked accelerated code";
  mpeg2dec_t* dec = mpeg2_init();
  const mpeg2_info_t* info = mpeg2_info(dec);
  std::vector<std::uint8_t> bytes(es);
  const std::uint8_t end[4] = {0, 0, 1, 0xB7};  // a sequence end code flushes the last picture
  bytes.insert(bytes.end(), end, end + 4);
  mpeg2_buffer(dec, bytes.data(), bytes.data() + bytes.size());
  std::vector<Yuv420Image> out;
  for (;;) {
    const mpeg2_state_t state = mpeg2_parse(dec);
    if (state == STATE_BUFFER) break;
    if ((state == STATE_SLICE || state == STATE_END || state == STATE_INVALID_END) && info->display_fbuf) {
      const mpeg2_sequence_t& s = *info->sequence;
      Yuv420Image img(static_cast<int>(s.picture_width), static_cast<int>(s.picture_height));
      for (int y = 0; y < img.height; ++y)
        std::copy_n(info->display_fbuf->buf[0] + static_cast<std::size_t>(y) * s.width, img.width,
                    img.y.begin() + static_cast<std::ptrdiff_t>(y) * img.width);
      for (int y = 0; y < (img.height + 1) / 2; ++y) {
        const std::size_t at = static_cast<std::size_t>(y) * s.chroma_width;
        const auto to = static_cast<std::ptrdiff_t>(y) * img.chromaWidth();
        std::copy_n(info->display_fbuf->buf[1] + at, img.chromaWidth(), img.cb.begin() + to);
        std::copy_n(info->display_fbuf->buf[2] + at, img.chromaWidth(), img.cr.begin() + to);
      }
      out.push_back(std::move(img));
    }
  }
  mpeg2_close(dec);
  return out;
}

std::vector<Yuv420Image> decodeOurs(const std::vector<std::uint8_t>& es, IdctKind kind, const Kernels& kernels) {
  DecoderOptions o;
  o.idct = kind;
  o.kernels = &kernels;
  Decoder dec(o);
  std::vector<Yuv420Image> out;
  for (const AccessUnit& au : splitAccessUnits(es)) {
    const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size));
    EXPECT_TRUE(r.clean()) << r.describe();
    if (!r.produced) continue;
    Yuv420Image img;
    copyToYuv420(dec.frame(), dec.width(), dec.height(), img);
    out.push_back(std::move(img));
  }
  return out;
}

// Per-picture share of differing samples between two kinds, over all cases: min and max in %.
struct Range {
  double lo = 100, hi = 0;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};
Range gPcsx2VsLibmpeg2, gExactVsLibmpeg2, gExactVsPcsx2;

double percentDifferent(const Yuv420Image& a, const Yuv420Image& b) {
  const testing::PlaneDiff d = testing::compare(a, b);
  EXPECT_LE(d.maxAbs, 1);
  return 100.0 * static_cast<double>(d.different) / static_cast<double>(d.samples);
}

void checkCase(const EncodeOptions& o) {
  SCOPED_TRACE(o.describe());
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  const std::vector<Yuv420Image> ref = decodeWithLibmpeg2(es);
  ASSERT_EQ(ref.size(), static_cast<std::size_t>(o.frames));
  for (const Kernels* k : {&scalarKernels(), &simdKernels()}) {
    SCOPED_TRACE(k->name);
    const std::vector<Yuv420Image> ours = decodeOurs(es, IdctKind::Libmpeg2, *k);
    ASSERT_EQ(ours.size(), ref.size());
    for (std::size_t f = 0; f < ours.size(); ++f) {
      ASSERT_EQ(ours[f].width, ref[f].width);
      ASSERT_EQ(ours[f].height, ref[f].height);
      const testing::PlaneDiff d = testing::compare(ours[f], ref[f]);
      EXPECT_EQ(d.different, 0u) << "frame " << f << ": " << d.different << " of " << d.samples
                                 << " samples differ from libmpeg2 (max " << d.maxAbs << ")";
    }
  }
  const std::vector<Yuv420Image> pcsx2 = decodeOurs(es, IdctKind::Pcsx2, simdKernels());
  const std::vector<Yuv420Image> exact = decodeOurs(es, IdctKind::Exact, simdKernels());
  for (std::size_t f = 0; f < ref.size(); ++f) {
    const double pl = percentDifferent(pcsx2[f], ref[f]);
    const double el = percentDifferent(exact[f], ref[f]);
    const double ep = percentDifferent(exact[f], pcsx2[f]);
    gPcsx2VsLibmpeg2.add(pl);
    gExactVsLibmpeg2.add(el);
    gExactVsPcsx2.add(ep);
    std::printf(
        "%-64s frame %zu: samples differing: pcsx2/libmpeg2 %.3f %%, exact/libmpeg2 %.3f %%, exact/pcsx2 %.3f %%\n",
        o.describe().c_str(), f, pl, el, ep);
  }
}

EncodeOptions base(Content c, int w = 256, int h = 256) {
  EncodeOptions o;
  o.width = w;
  o.height = h;
  o.frames = 3;
  o.content = c;
  o.quantiser = 4;
  return o;
}

TEST(IpuLibmpeg2Stream, Mpeg2Quantisers) {
  for (int q : {1, 2, 4, 8, 16, 31}) {
    EncodeOptions o = base(q < 4 ? Content::kNoise : Content::kBusy);
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuLibmpeg2Stream, Mpeg2Lightmap) {
  for (int q : {2, 6}) {
    EncodeOptions o = base(Content::kLightmap, 512, 512);
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuLibmpeg2Stream, Mpeg2CodingOptions) {
  EncodeOptions a = base(Content::kInterlaced, 320, 256);
  a.interlacedDct = true;
  a.quantiser = 3;
  checkCase(a);
  EncodeOptions b = base(Content::kNoise);
  b.alternateScan = true;
  b.quantiser = 2;
  checkCase(b);
  EncodeOptions c = base(Content::kBusy);
  c.nonLinearQuant = true;
  c.quantiser = 9;
  checkCase(c);
  EncodeOptions d = base(Content::kNoise);
  d.intraVlc = true;
  d.quantiser = 1;
  checkCase(d);
  EncodeOptions e = base(Content::kInterlaced, 288, 272);
  e.intraVlc = e.alternateScan = e.nonLinearQuant = e.customMatrix = e.interlacedDct = true;
  e.dcPrecision = 2;
  e.quantiser = 5;
  checkCase(e);
}

TEST(IpuLibmpeg2Stream, Mpeg1) {
  for (int q : {1, 4, 31}) {
    EncodeOptions o = base(q == 1 ? Content::kNoise : Content::kBusy);
    o.mpeg1 = true;
    o.quantiser = q;
    checkCase(o);
  }
}

TEST(IpuLibmpeg2Stream, Summary) {
  std::printf(
      "per picture, %% of samples differing: pcsx2 vs libmpeg2 %.3f-%.3f, exact vs libmpeg2 %.3f-%.3f, "
      "exact vs pcsx2 %.3f-%.3f\n",
      gPcsx2VsLibmpeg2.lo, gPcsx2VsLibmpeg2.hi, gExactVsLibmpeg2.lo, gExactVsLibmpeg2.hi, gExactVsPcsx2.lo,
      gExactVsPcsx2.hi);
}

}  // namespace
}  // namespace vbim::ipu
