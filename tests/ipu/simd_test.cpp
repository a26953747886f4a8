// The Highway kernels against the scalar reference, on every instruction set this machine
// supports: the inverse DCT and the RGB32 conversion must give the same bytes.
#include <gtest/gtest.h>

#include <hwy/targets.h>

#include <algorithm>
#include <cmath>

#include "ipu/elementary_stream.hpp"
#include "ipu/idct.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "runtime/simd/targets.hpp"
#include "tests/ipu/support/idct_blocks.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using testing::Lcg;

template <class F>
void forEachTarget(F&& f) {
  vbim::simd::forEachTarget(HWY_TARGETS, [&](std::int64_t target) {
    SCOPED_TRACE(hwy::TargetName(target));
    f();
  });
}

TEST(IpuSimd, IdctMatchesScalar) {
  forEachTarget([] {
    Lcg rng{7};
    for (int t = 0; t < 20000; ++t) {
      std::int16_t block[64] = {};
      unsigned rows = 0, cols = 0;
      const int kind = t % 4;
      const int count = kind == 0 ? 64 : 1 + rng.below(6);
      for (int k = 0; k < count; ++k) {
        const int pos = kind == 0 ? k : rng.below(64);
        int v;
        if (kind == 3) {
          v = rng.below(2) ? 2047 : -2048;  // the saturated extremes
        } else {
          const int range = kind == 1 ? 2048 : 300;
          v = rng.below(2 * range) - range;
        }
        block[pos] = static_cast<std::int16_t>(v);
        rows |= 1u << (pos >> 3);
        cols |= 1u << (pos & 7);
      }
      if (t % 3 == 0) {
        // The mismatch toggle alone in row 7 and column 7, flagged as the decoder does.
        for (int i = 0; i < 8; ++i) block[56 + i] = block[8 * i + 7] = 0;
        block[63] = static_cast<std::int16_t>(rng.below(2) ? 1 : -1);
        rows = (rows & 0x7F) | kIdctToggleOnly;
        cols &= 0x7F;
      }
      std::uint8_t a[8 * 9], b[8 * 9];
      scalarKernels().idctOf(IdctKind::Exact).copy(block, rows, cols, a, 9);
      idctSimd(block, rows, cols, b, 9);
      for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) ASSERT_EQ(a[y * 9 + x], b[y * 9 + x]) << "block " << t;
    }
    // The adversarial worst case for the 32-bit split: signs following the basis everywhere.
    for (int s : {1, -1}) {
      std::int16_t block[64];
      for (int i = 0; i < 64; ++i) block[i] = static_cast<std::int16_t>(((i * 5 + i / 8) % 3 ? 2047 : -2048) * s);
      std::uint8_t a[64], b[64];
      idctScalar(block, 0xFF, a, 8);
      idctSimd(block, 0xFF, 0xFF, b, 8);
      for (int i = 0; i < 64; ++i) ASSERT_EQ(a[i], b[i]);
    }
    // The largest sums the transform can see: for each output (x, y), every coefficient at the
    // extreme with the sign of its basis product there (an overflow would flip the clamped pixel).
    for (int y0 = 0; y0 < 8; ++y0)
      for (int x0 = 0; x0 < 8; ++x0)
        for (int s : {1, -1}) {
          std::int16_t block[64];
          for (int v = 0; v < 8; ++v)
            for (int u = 0; u < 8; ++u) {
              const double c = std::cos((2 * x0 + 1) * u * M_PI / 16) * std::cos((2 * y0 + 1) * v * M_PI / 16);
              block[8 * v + u] = static_cast<std::int16_t>((c * s >= 0) ? 2047 : -2048);
            }
          std::uint8_t a[64], b[64];
          idctScalar(block, 0xFF, a, 8);
          idctSimd(block, 0xFF, 0xFF, b, 8);
          for (int i = 0; i < 64; ++i) ASSERT_EQ(a[i], b[i]) << "x " << x0 << " y " << y0 << " sign " << s;
        }
  });
}

// The libmpeg2-family kernels and every kind's non-intra entry: scalar and SIMD give the same bytes
// on sparse, dense and extreme blocks, with and without the toggle and the first-only flag.
TEST(IpuSimd, EveryIdctKindMatchesScalar) {
  forEachTarget([] {
    for (IdctKind kind : kAllIdctKinds) {
      SCOPED_TRACE(idctKindName(kind));
      const IdctKernels& s = scalarKernels().idctOf(kind);
      const Kernels target = simdKernelsOfCurrentTarget();
      const IdctKernels& v = target.idctOf(kind);
      Lcg rng{17};
      for (int t = 0; t < 40000; ++t) {
        const testing::IdctBlock b = testing::makeIdctBlock(t, rng);
        std::uint8_t a[8 * 9], c[8 * 9];
        s.copy(b.c, b.rows & 0x1FF, b.cols, a, 9);
        v.copy(b.c, b.rows & 0x1FF, b.cols, c, 9);
        for (int y = 0; y < 8; ++y)
          for (int x = 0; x < 8; ++x) ASSERT_EQ(a[y * 9 + x], c[y * 9 + x]) << "copy, block " << t;
        for (int i = 0; i < 8 * 9; ++i) a[i] = c[i] = static_cast<std::uint8_t>(rng.below(256));
        s.add(b.c, b.rows, b.cols, a, 9);
        v.add(b.c, b.rows, b.cols, c, 9);
        for (int i = 0; i < 8 * 9; ++i) ASSERT_EQ(a[i], c[i]) << "add, block " << t;
      }
      // Every DC value and toggle sign, intra and non-intra (first-only or not).
      for (int dc = -2048; dc <= 2047; ++dc)
        for (int toggle : {0, 1, -1}) {
          std::int16_t blk[64] = {};
          blk[0] = static_cast<std::int16_t>(dc);
          blk[63] = static_cast<std::int16_t>(toggle);
          const unsigned rows = 1u | (toggle ? kIdctToggleOnly : 0u);
          std::uint8_t a[64], c[64];
          s.copy(blk, rows, 1, a, 8);
          v.copy(blk, rows, 1, c, 8);
          for (int i = 0; i < 64; ++i) ASSERT_EQ(a[i], c[i]) << "dc " << dc << " toggle " << toggle;
          for (unsigned first : {0u, kIdctFirstOnly}) {
            std::fill(a, a + 64, std::uint8_t{100});
            std::fill(c, c + 64, std::uint8_t{100});
            s.add(blk, rows | first, 1, a, 8);
            v.add(blk, rows | first, 1, c, 8);
            for (int i = 0; i < 64; ++i) ASSERT_EQ(a[i], c[i]) << "add dc " << dc << " toggle " << toggle;
          }
        }
    }
  });
}

// The masks the P/B parse gives (ipu/inter_slice_decoder.cpp): only the rows and columns that hold
// a coded coefficient (row 0 not forced), with the mismatch toggle alone in row 7 and column 7
// (kIdctToggleOnly) beside few rows, the case the kernels take apart from the full transform.
TEST(IpuSimd, TightMasksAndToggleMatchScalar) {
  forEachTarget([] {
    const Kernels target = simdKernelsOfCurrentTarget();
    for (IdctKind kind : kAllIdctKinds) {
      SCOPED_TRACE(idctKindName(kind));
      const IdctKernels& s = scalarKernels().idctOf(kind);
      const IdctKernels& v = target.idctOf(kind);
      Lcg rng{29};
      for (int t = 0; t < 20000; ++t) {
        std::int16_t blk[64] = {};
        unsigned rows = 0, cols = 0;
        const int maxRow = 1 + rng.below(t % 2 ? 4 : 7), maxCol = 1 + rng.below(7);
        const int count = 1 + rng.below(6);
        const int range = t % 5 == 0 ? 2048 : 200;
        for (int k = 0; k < count; ++k) {
          const int pos = 8 * rng.below(maxRow) + rng.below(maxCol);
          blk[pos] = static_cast<std::int16_t>(rng.below(2 * range) - range);
          rows |= 1u << (pos >> 3);
          cols |= 1u << (pos & 7);
        }
        if (t % 3 != 0) {
          blk[63] = static_cast<std::int16_t>(rng.below(2) ? 1 : -1);
          rows |= kIdctToggleOnly;
        }
        std::uint8_t a[8 * 9], c[8 * 9];
        s.copy(blk, rows, cols, a, 9);
        v.copy(blk, rows, cols, c, 9);
        for (int y = 0; y < 8; ++y)
          for (int x = 0; x < 8; ++x) ASSERT_EQ(a[y * 9 + x], c[y * 9 + x]) << "copy, block " << t;
        for (int i = 0; i < 8 * 9; ++i) a[i] = c[i] = static_cast<std::uint8_t>(rng.below(256));
        s.add(blk, rows, cols, a, 9);
        v.add(blk, rows, cols, c, 9);
        for (int i = 0; i < 8 * 9; ++i) ASSERT_EQ(a[i], c[i]) << "add, block " << t;
      }
    }
  });
}

// The 2- and 4-row forms of the libmpeg2-family kernels with row results beyond 16 bits: both
// decoders store the row pass in 16 bits (wrapping), and the kernels take those low 16 bits into
// the column pass's 16-bit pairs. Rows below R at the extremes with the signs of one output
// column's basis (row results ~ +-122,000), with and without the mismatch toggle in row 7.
TEST(IpuSimd, ShortFormsWrapRowResultsAsScalar) {
  // The row result at the chosen column, |sum_u F[u] B(u, x)| / 256 with B(0) = 2048 and
  // |B(u)| = 2048 sqrt(2) |cos((2x + 1) u pi / 16)|: beyond int16, so the test reaches the wrap.
  for (int x0 = 0; x0 < 8; ++x0) {
    double sum = 2048;
    for (int u = 1; u < 8; ++u) sum += 2048 * std::sqrt(2.0) * std::abs(std::cos((2 * x0 + 1) * u * M_PI / 16));
    ASSERT_GT(2047 * sum / 256, 65536.0) << "column " << x0;
  }
  forEachTarget([] {
    const Kernels target = simdKernelsOfCurrentTarget();
    for (IdctKind kind : {IdctKind::Pcsx2, IdctKind::Libmpeg2}) {
      SCOPED_TRACE(idctKindName(kind));
      const IdctKernels& s = scalarKernels().idctOf(kind);
      const IdctKernels& v = target.idctOf(kind);
      for (int rowsUsed : {2, 4})
        for (int x0 = 0; x0 < 8; ++x0)
          for (int sign : {1, -1})
            for (int toggle : {0, 1, -1}) {
              std::int16_t blk[64] = {};
              for (int r = 0; r < rowsUsed; ++r)
                for (int u = 0; u < (toggle ? 7 : 8); ++u) {
                  const double c = std::cos((2 * x0 + 1) * u * M_PI / 16) * ((r & 1) ? -sign : sign);
                  blk[8 * r + u] = static_cast<std::int16_t>(c >= 0 ? 2047 : -2047);
                }
              blk[63] = static_cast<std::int16_t>(toggle);
              const unsigned rows = ((1u << rowsUsed) - 1) | (toggle ? kIdctToggleOnly : 0u);
              const unsigned cols = toggle ? 0x7Fu : 0xFFu;
              std::uint8_t a[64], c[64];
              s.copy(blk, rows, cols, a, 8);
              v.copy(blk, rows, cols, c, 8);
              for (int i = 0; i < 64; ++i)
                ASSERT_EQ(a[i], c[i]) << "copy, rows " << rowsUsed << " column " << x0 << " toggle " << toggle;
              for (int i = 0; i < 64; ++i) a[i] = c[i] = static_cast<std::uint8_t>(37 * i);
              s.add(blk, rows, cols, a, 8);
              v.add(blk, rows, cols, c, 8);
              for (int i = 0; i < 64; ++i)
                ASSERT_EQ(a[i], c[i]) << "add, rows " << rowsUsed << " column " << x0 << " toggle " << toggle;
            }
    }
  });
}

TEST(IpuSimd, CscMatchesScalar) {
  forEachTarget([] {
    Lcg rng{11};
    // Widths below, at and just past each target's step (8 to 64 pixels), odd ones, and 720 (a last
    // step that overlaps the one before it).
    for (int width : {1, 2, 7, 15, 16, 17, 31, 32, 33, 47, 48, 63, 64, 65, 100, 512, 719, 720}) {
      for (CscThresholds th :
           {CscThresholds{}, CscThresholds{40, 100}, CscThresholds{0, 300}, CscThresholds{511, 511}}) {
        // Two luma lines sharing one chroma line, as the frame conversion calls it.
        std::vector<std::uint8_t> y(2 * static_cast<std::size_t>(width)), cb((width + 1) / 2), cr((width + 1) / 2);
        for (auto& v : y) v = static_cast<std::uint8_t>(rng.below(256));
        for (auto& v : cb) v = static_cast<std::uint8_t>(rng.below(256));
        for (auto& v : cr) v = static_cast<std::uint8_t>(rng.below(256));
        std::vector<std::uint8_t> a(2 * static_cast<std::size_t>(width) * 4), b(a.size()), one(a.size() / 2);
        for (int line = 0; line < 2; ++line)
          cscRowRgba32Scalar(y.data() + line * width, cb.data(), cr.data(), width, a.data() + line * width * 4, th);
        cscRowsRgba32Simd(y.data(), width, 2, cb.data(), cr.data(), width, b.data(), width * 4, th);
        ASSERT_EQ(a, b) << "width " << width << " th " << th.th0 << "," << th.th1;
        cscRowsRgba32Simd(y.data(), 0, 1, cb.data(), cr.data(), width, one.data(), 0, th);
        ASSERT_TRUE(std::equal(one.begin(), one.end(), a.begin())) << "one line, width " << width;
      }
    }
    // Every Y against a sweep of chroma.
    std::vector<std::uint8_t> y(256), cb(128), cr(128), a(1024), b(1024);
    for (int c = 0; c < 256; c += 5) {
      for (int i = 0; i < 256; ++i) y[i] = static_cast<std::uint8_t>(i);
      for (int i = 0; i < 128; ++i) {
        cb[i] = static_cast<std::uint8_t>(c);
        cr[i] = static_cast<std::uint8_t>(255 - c + i);
      }
      cscRowRgba32Scalar(y.data(), cb.data(), cr.data(), 256, a.data(), {});
      cscRowsRgba32Simd(y.data(), 0, 1, cb.data(), cr.data(), 256, b.data(), 0, {});
      ASSERT_EQ(a, b);
    }
  });
}

TEST(IpuSimd, WholeDecodeMatchesScalar) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 80;
  o.frames = 2;
  o.quantiser = 2;
  o.content = testing::Content::kNoise;
  const auto es = testing::encodeIntra(o);
  for (IdctKind kind : kAllIdctKinds) {
    SCOPED_TRACE(idctKindName(kind));
    DecoderOptions scalar, simd;
    scalar.idct = simd.idct = kind;
    simd.kernels = &simdKernels();
    Decoder a(scalar), b(simd);
    for (const AccessUnit& au : splitAccessUnits(es)) {
      a.decode(std::span(es).subspan(au.offset, au.size));
      b.decode(std::span(es).subspan(au.offset, au.size));
      EXPECT_EQ(a.frame().y, b.frame().y);
      EXPECT_EQ(a.frame().cb, b.frame().cb);
      EXPECT_EQ(a.frame().cr, b.frame().cr);
      Rgba8Image ra, rb;
      convertToRgba32(a.frame(), a.width(), a.height(), {}, ra);
      convertToRgba32(b.frame(), b.width(), b.height(), {}, rb, cscRowsRgba32Simd);
      EXPECT_EQ(ra.pixels, rb.pixels);
    }
  }
  std::printf("SIMD target: %s\n", simdTargetName());
}

}  // namespace
}  // namespace vbim::ipu
