// The inverse DCT against IEEE Std 1180-1990: the standard's random block generator, ranges,
// forward DCT in double precision, and its accuracy limits; plus the decoder's DC fast paths,
// which must give exactly what the full transform gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "ipu/idct.hpp"
#include "ipu/idct_libmpeg2.hpp"
#include "ipu/kernels.hpp"

namespace vbim::ipu {
namespace {

// IEEE 1180-1990 §3.2: the pseudo-random generator (its `long` arithmetic is 32 bits, wrapping).
class Ieee1180Random {
 public:
  int next(int lo, int hi) {  // uniformly in [-lo, hi]
    randx_ = randx_ * 1103515245u + 12345u;
    const std::uint32_t i = randx_ & 0x7ffffffeu;
    double x = static_cast<double>(i) / static_cast<double>(0x7fffffff);
    x *= (lo + hi + 1);
    const int j = static_cast<int>(x);
    return j - lo;
  }

 private:
  std::uint32_t randx_ = 1;
};

double c(int u) {
  return u == 0 ? std::sqrt(0.125) : 0.5;
}

// Separable double-precision transforms (the standard's reference is the direct formula; the
// separable form is the same to well below the tolerances).
void forwardDct(const double in[64], double out[64]) {
  double tmp[64];
  for (int y = 0; y < 8; ++y)
    for (int u = 0; u < 8; ++u) {
      double s = 0;
      for (int x = 0; x < 8; ++x) s += in[8 * y + x] * std::cos((2 * x + 1) * u * M_PI / 16);
      tmp[8 * y + u] = c(u) * s;
    }
  for (int u = 0; u < 8; ++u)
    for (int v = 0; v < 8; ++v) {
      double s = 0;
      for (int y = 0; y < 8; ++y) s += tmp[8 * y + u] * std::cos((2 * y + 1) * v * M_PI / 16);
      out[8 * v + u] = c(v) * s;
    }
}

void inverseDct(const double in[64], double out[64]) {
  double tmp[64];
  for (int v = 0; v < 8; ++v)
    for (int x = 0; x < 8; ++x) {
      double s = 0;
      for (int u = 0; u < 8; ++u) s += c(u) * in[8 * v + u] * std::cos((2 * x + 1) * u * M_PI / 16);
      tmp[8 * v + x] = s;
    }
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y) {
      double s = 0;
      for (int v = 0; v < 8; ++v) s += c(v) * tmp[8 * v + x] * std::cos((2 * y + 1) * v * M_PI / 16);
      out[8 * y + x] = s;
    }
}

int clampRound(double v, int lo, int hi) {
  const double r = std::floor(v + 0.5);
  return static_cast<int>(r < lo ? lo : (r > hi ? hi : r));
}

struct Stats {
  int peak = 0;
  double pmse = 0, omse = 0, pme = 0, ome = 0;
};

// The kind's signed result clipped to [-256, 255], the standard's test interface.
void idctSignedOf(IdctKind kind, const std::int16_t* block, std::int16_t* out) {
  if (kind == IdctKind::Exact) return idctSigned(block, out);
  (kind == IdctKind::Pcsx2 ? idctPcsx2 : idctLibmpeg2)(block, out);
  for (int i = 0; i < 64; ++i) out[i] = static_cast<std::int16_t>(std::clamp<int>(out[i], -256, 255));
}

Stats runIeee1180(IdctKind kind, int lo, int hi, int sign, int blocks) {
  Ieee1180Random rng;
  long long sumErr[64] = {}, sumSq[64] = {};
  int peak = 0;
  for (int b = 0; b < blocks; ++b) {
    double pixels[64], coef[64], ref[64];
    for (int i = 0; i < 64; ++i) {
      pixels[i] = sign * rng.next(lo, hi);
    }
    forwardDct(pixels, coef);
    std::int16_t block[64];
    double rounded[64];
    for (int i = 0; i < 64; ++i) {
      block[i] = static_cast<std::int16_t>(clampRound(coef[i], -2048, 2047));
      rounded[i] = block[i];
    }
    inverseDct(rounded, ref);
    std::int16_t test[64];
    idctSignedOf(kind, block, test);
    for (int i = 0; i < 64; ++i) {
      const int e = test[i] - clampRound(ref[i], -256, 255);
      peak = std::max(peak, std::abs(e));
      sumErr[i] += e;
      sumSq[i] += e * e;
    }
  }
  Stats s;
  s.peak = peak;
  double totErr = 0, totSq = 0;
  for (int i = 0; i < 64; ++i) {
    s.pme = std::max(s.pme, std::fabs(static_cast<double>(sumErr[i]) / blocks));
    s.pmse = std::max(s.pmse, static_cast<double>(sumSq[i]) / blocks);
    totErr += sumErr[i];
    totSq += sumSq[i];
  }
  s.ome = std::fabs(totErr / (64.0 * blocks));
  s.omse = totSq / (64.0 * blocks);
  return s;
}

// The standard's procedure for each kind: 10,000 blocks per range and sign, the figures printed
// (recorded in ipu/README.md) and held to the standard's limits: peak error 1, per-pixel MSE 0.06,
// overall MSE 0.02, per-pixel mean error 0.015, overall mean error 0.0015.
class IpuIdctIeee1180 : public testing::TestWithParam<IdctKind> {};

TEST_P(IpuIdctIeee1180, MeetsTheStandard) {
  struct Range {
    int lo, hi;
  };
  for (Range r : {Range{256, 255}, Range{5, 5}, Range{300, 300}}) {
    for (int sign : {1, -1}) {
      SCOPED_TRACE(testing::Message() << "range -" << r.lo << ".." << r.hi << " sign " << sign);
      const Stats s = runIeee1180(GetParam(), r.lo, r.hi, sign, 10000);
      EXPECT_LE(s.peak, 1);
      EXPECT_LE(s.pmse, 0.06);
      EXPECT_LE(s.omse, 0.02);
      EXPECT_LE(s.pme, 0.015);
      EXPECT_LE(s.ome, 0.0015);
      std::printf("IEEE 1180 %-8s -%d..%d sign %+d: peak %d pmse %.4f omse %.5f pme %.4f ome %.5f\n",
                  idctKindName(GetParam()), r.lo, r.hi, sign, s.peak, s.pmse, s.omse, s.pme, s.ome);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, IpuIdctIeee1180, testing::ValuesIn(kAllIdctKinds),
                         [](const testing::TestParamInfo<IdctKind>& i) { return std::string(idctKindName(i.param)); });

TEST(IpuIdct, ZeroInZeroOut) {
  for (IdctKind kind : kAllIdctKinds) {
    std::int16_t block[64] = {}, out[64];
    idctSignedOf(kind, block, out);
    for (int i = 0; i < 64; ++i) EXPECT_EQ(out[i], 0) << idctKindName(kind);
  }
}

// The decoder fills DC-only intra blocks with idctDcValue(dc) = (dc + 4) >> 3, and a DC that is a
// multiple of 8 plus the mismatch-control toggle of F[7][7] (kIdctToggleOnly) with the same value:
// for every kind, both must equal the full transform, for every DC value and toggle sign.
TEST(IpuIdct, DcFastPathsAreExact) {
  for (IdctKind kind : kAllIdctKinds) {
    const IdctKernels& k = scalarKernels().idctOf(kind);
    for (int dc = -2048; dc <= 2047; ++dc) {
      std::int16_t block[64] = {};
      block[0] = static_cast<std::int16_t>(dc);
      std::uint8_t full[64];
      k.copy(block, 0xFF, 0xFF, full, 8);
      for (int i = 0; i < 64; ++i) ASSERT_EQ(full[i], idctDcValue(dc)) << idctKindName(kind) << " dc " << dc;
      if (dc % 8 == 0) {
        for (int toggle : {1, -1}) {
          block[63] = static_cast<std::int16_t>(toggle);
          k.copy(block, 0xFF, 0xFF, full, 8);
          for (int i = 0; i < 64; ++i)
            ASSERT_EQ(full[i], idctDcValue(dc)) << idctKindName(kind) << " dc " << dc << " toggle " << toggle;
        }
      }
    }
  }
}

// The exact kind's non-intra constant shortcut (kIdctFirstOnly, exactIdctIsConstant) gives the
// bytes of its full transform for every DC, with and without the mismatch toggle, on predictions
// that include the clip's ends.
TEST(IpuIdct, ExactAddConstantShortcutIsExact) {
  const IdctAddFn add = scalarKernels().idctOf(IdctKind::Exact).add;
  int constant = 0;
  for (int dc = -2048; dc <= 2047; ++dc) {
    for (const int f77 : {0, 1}) {
      std::int16_t block[64] = {};
      block[0] = static_cast<std::int16_t>(dc);
      block[63] = static_cast<std::int16_t>(f77);
      if (exactIdctIsConstant(dc, f77)) {
        ++constant;
        std::int16_t full[64];
        idctSignedUnclipped(block, 0xFF, full);
        for (int i = 0; i < 64; ++i) ASSERT_EQ(full[i], exactIdctConstant(dc)) << "dc " << dc << " f77 " << f77;
      }
      std::uint8_t shortcut[64], whole[64];
      for (int i = 0; i < 64; ++i) shortcut[i] = whole[i] = static_cast<std::uint8_t>(i * 37 % 256 | (i % 5 ? 0 : 255));
      add(block, 0xFF | kIdctFirstOnly, 0xFF, shortcut, 8);
      add(block, 0xFF, 0xFF, whole, 8);
      for (int i = 0; i < 64; ++i) ASSERT_EQ(shortcut[i], whole[i]) << "dc " << dc << " f77 " << f77;
    }
  }
  EXPECT_EQ(constant, 4096 + 4096 * 5 / 8);
}

// Skipping rows the mask says are zero gives the same result as transforming all of them.
TEST(IpuIdct, RowMaskSkipsOnlyZeroRows) {
  Ieee1180Random rng;
  for (int t = 0; t < 2000; ++t) {
    std::int16_t block[64] = {};
    unsigned mask = 0;
    for (int r = 0; r < 8; ++r) {
      if (rng.next(0, 1)) {
        mask |= 1u << r;
        for (int x = 0; x < 8; ++x) block[8 * r + x] = static_cast<std::int16_t>(rng.next(300, 300));
      }
    }
    std::uint8_t a[64], b[64];
    idctScalar(block, mask, a, 8);
    idctScalar(block, 0xFF, b, 8);
    for (int i = 0; i < 64; ++i) ASSERT_EQ(a[i], b[i]);
  }
}

// Extreme inputs (the saturated range at full strength) stay defined: no overflow, clamped output.
TEST(IpuIdct, ExtremeInputsAreClamped) {
  for (int s : {2047, -2048}) {
    std::int16_t block[64];
    for (int i = 0; i < 64; ++i) block[i] = static_cast<std::int16_t>((i * 7) % 3 ? s : -s - 1);
    std::int16_t out[64];
    idctSigned(block, out);
    for (int i = 0; i < 64; ++i) {
      EXPECT_GE(out[i], -256);
      EXPECT_LE(out[i], 255);
    }
  }
}

}  // namespace
}  // namespace vbim::ipu
