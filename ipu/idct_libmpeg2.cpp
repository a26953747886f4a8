#include "ipu/idct_libmpeg2.hpp"

#include <cstddef>

namespace vbim::ipu {
namespace {

// W_k = round(2048 * sqrt(2) * cos(k pi / 16)): the constants both decoders use (11 fractional bits).
constexpr std::int64_t kW1 = 2841;
constexpr std::int64_t kW2 = 2676;
constexpr std::int64_t kW3 = 2408;
constexpr std::int64_t kW5 = 1609;
constexpr std::int64_t kW6 = 1108;
constexpr std::int64_t kW7 = 565;
// 181 / 256 ~ sqrt(1/2): the odd part's rotation by pi/4.
constexpr std::int64_t kHalfSqrt2 = 181;

// The reference decoders compute in C `int` (32-bit two's complement in practice); the sums are
// kept in 64 bits here and brought back to 32 bits where the C arithmetic would wrap.
constexpr std::int32_t wrap32(std::int64_t v) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(v)));
}
// A pass's result goes back into the 16-bit block.
constexpr std::int16_t store16(std::int64_t v) {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(static_cast<std::uint64_t>(v)));
}

// One 1-D pass over x[0..7] (coefficients in natural order, stride `step`), shared by both forms.
// Even part: a0..a3 from x0, x2, x4, x6 with x0, x4 scaled by 2^11 and `bias` added to x0; odd
// part: b0..b3 from x1, x3, x5, x7. Out: (a + b) >> shift into 16 bits.
struct PassForm {
  std::int64_t bias;   // rounding term added to x0 << 11
  int shift;           // final shift
  bool preShiftOdd;    // the 181 factor applied to ((t0 +- t1) >> 8) instead of ((t0 +- t1) * 181) >> 8
  bool preShiftTerms;  // PCSX2's column pass: t0 and t1 each shifted by 8 before the sum
};

void pass(std::int16_t* x, std::ptrdiff_t step, const PassForm& f) {
  const std::int64_t x0 = x[0], x1 = x[step], x2 = x[2 * step], x3 = x[3 * step], x4 = x[4 * step], x5 = x[5 * step],
                     x6 = x[6 * step], x7 = x[7 * step];
  const std::int64_t d0 = wrap32(x0 * 2048 + f.bias);
  const std::int64_t d4 = wrap32(x4 * 2048);
  const std::int64_t e0 = wrap32(d0 + d4);
  const std::int64_t e1 = wrap32(d0 - d4);
  const std::int64_t e2 = wrap32(kW6 * x6 + kW2 * x2);  // the cos(2 pi/16), cos(6 pi/16) rotation
  const std::int64_t e3 = wrap32(kW6 * x2 - kW2 * x6);
  const std::int64_t a0 = wrap32(e0 + e2), a1 = wrap32(e1 + e3), a2 = wrap32(e1 - e3), a3 = wrap32(e0 - e2);

  const std::int64_t o0 = wrap32(kW7 * x7 + kW1 * x1);  // rotation by 1 pi/16 and 7 pi/16
  const std::int64_t o1 = wrap32(kW7 * x1 - kW1 * x7);
  const std::int64_t o2 = wrap32(kW3 * x3 + kW5 * x5);  // rotation by 3 pi/16 and 5 pi/16
  const std::int64_t o3 = wrap32(kW3 * x5 - kW5 * x3);
  const std::int64_t b0 = wrap32(o0 + o2);
  const std::int64_t b3 = wrap32(o1 + o3);
  std::int64_t u = wrap32(o0 - o2);
  std::int64_t v = wrap32(o1 - o3);
  std::int64_t b1 = 0;
  std::int64_t b2 = 0;
  if (f.preShiftTerms) {
    u >>= 8;
    v >>= 8;
    b1 = wrap32((u + v) * kHalfSqrt2);
    b2 = wrap32((u - v) * kHalfSqrt2);
  } else if (f.preShiftOdd) {
    b1 = wrap32((wrap32(u + v) >> 8) * kHalfSqrt2);
    b2 = wrap32((wrap32(u - v) >> 8) * kHalfSqrt2);
  } else {
    b1 = wrap32(wrap32(u + v) * kHalfSqrt2) >> 8;
    b2 = wrap32(wrap32(u - v) * kHalfSqrt2) >> 8;
  }
  x[0] = store16(wrap32(a0 + b0) >> f.shift);
  x[step] = store16(wrap32(a1 + b1) >> f.shift);
  x[2 * step] = store16(wrap32(a2 + b2) >> f.shift);
  x[3 * step] = store16(wrap32(a3 + b3) >> f.shift);
  x[4 * step] = store16(wrap32(a3 - b3) >> f.shift);
  x[5 * step] = store16(wrap32(a2 - b2) >> f.shift);
  x[6 * step] = store16(wrap32(a1 - b1) >> f.shift);
  x[7 * step] = store16(wrap32(a0 - b0) >> f.shift);
}

bool onlyFirst(const std::int16_t* row) {
  return (row[1] | row[2] | row[3] | row[4] | row[5] | row[6] | row[7]) == 0;
}

// Row passes, then column passes, on a copy held in 16-bit samples. `Scale` multiplies each
// coefficient on entry (16 for libmpeg2 0.5.1's 4 fractional bits).
template <int Scale>
void transform(const std::int16_t* coeffs, std::int16_t* out, const PassForm& rowForm, const PassForm& colForm) {
  std::int16_t b[64];
  for (int i = 0; i < 64; ++i) b[i] = store16(std::int64_t{coeffs[i]} * Scale);
  for (int r = 0; r < 8; ++r) {
    std::int16_t* row = b + static_cast<std::ptrdiff_t>(8 * r);
    if (onlyFirst(row)) {
      // The row shortcut of both decoders (x0 * 8 in 16 bits, from x0 << 3 or (16 x0) >> 1); the
      // general pass gives the same value, since the bias is below 2^shift.
      const std::int16_t v = store16((std::int64_t{row[0]} * 8) / Scale);
      for (int n = 0; n < 8; ++n) row[n] = v;
    } else {
      pass(row, 1, rowForm);
    }
  }
  for (int c = 0; c < 8; ++c) pass(b + c, 8, colForm);
  for (int i = 0; i < 64; ++i) out[i] = b[i];
}

}  // namespace

void idctPcsx2(const std::int16_t* coeffs, std::int16_t* out) {
  static constexpr PassForm kRow{128, 8, false, false};
  static constexpr PassForm kCol{65536, 17, false, true};
  transform<1>(coeffs, out, kRow, kCol);
}

void idctLibmpeg2(const std::int16_t* coeffs, std::int16_t* out) {
  static constexpr PassForm kRow{2048, 12, true, false};
  static constexpr PassForm kCol{65536, 17, true, false};
  transform<16>(coeffs, out, kRow, kCol);
}

}  // namespace vbim::ipu
