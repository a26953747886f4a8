#include "ipu/simd/mc_kernels.hpp"

#include <cstddef>
#include <cstdint>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ipu/simd/mc_kernels.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace vbim::ipu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET != HWY_SCALAR
// The four-sample interpolation (a + b + c + d + 2) >> 2 in bytes: with ab = (a + b + 1) >> 1 and
// cd = (c + d + 1) >> 1, (ab + cd + 1) >> 1 is one too large exactly when a + b or c + d is odd
// and ab + cd is odd (write a + b = 2p + e, c + d = 2q + f and compare the two floors), so
// subtracting ((a ^ b) | (c ^ d)) & (ab ^ cd) & 1 gives the exact result.
template <class D, class V>
HWY_INLINE V average4(D d, V a, V b, V c, V e) {
  const V ab = hn::AverageRound(a, b);
  const V ce = hn::AverageRound(c, e);
  const V odd = hn::And(hn::And(hn::Or(hn::Xor(a, b), hn::Xor(c, e)), hn::Xor(ab, ce)), hn::Set(d, 1));
  return hn::Sub(hn::AverageRound(ab, ce), odd);
}

template <bool Average, class D, class V>
HWY_INLINE void store(D d, V p, std::uint8_t* dst) {
  if constexpr (Average) p = hn::AverageRound(hn::LoadU(d, dst), p);
  hn::StoreU(p, d, dst);
}

template <bool Average, int Width, int Case>
void predictImpl(std::uint8_t* HWY_RESTRICT dst, std::ptrdiff_t dstStride, const std::uint8_t* HWY_RESTRICT src,
                 std::ptrdiff_t srcStride, int rows) {
  const hn::FixedTag<std::uint8_t, Width> d;
  if constexpr (Case == 0) {
    for (int r = 0; r < rows; ++r) store<Average>(d, hn::LoadU(d, src + r * srcStride), dst + r * dstStride);
  } else if constexpr (Case == 1) {
    for (int r = 0; r < rows; ++r) {
      const std::uint8_t* p = src + r * srcStride;
      store<Average>(d, hn::AverageRound(hn::LoadU(d, p), hn::LoadU(d, p + 1)), dst + r * dstStride);
    }
  } else if constexpr (Case == 2) {
    auto above = hn::LoadU(d, src);
    for (int r = 0; r < rows; ++r) {
      const auto below = hn::LoadU(d, src + (r + 1) * srcStride);
      store<Average>(d, hn::AverageRound(above, below), dst + r * dstStride);
      above = below;
    }
  } else {
    auto a = hn::LoadU(d, src);
    auto b = hn::LoadU(d, src + 1);
    for (int r = 0; r < rows; ++r) {
      const std::uint8_t* p = src + (r + 1) * srcStride;
      const auto c = hn::LoadU(d, p);
      const auto e = hn::LoadU(d, p + 1);
      store<Average>(d, average4(d, a, b, c, e), dst + r * dstStride);
      a = c;
      b = e;
    }
  }
}

template <bool Average, int Width>
void fill(McPredictFn (&out)[4]) {
  out[0] = predictImpl<Average, Width, 0>;
  out[1] = predictImpl<Average, Width, 1>;
  out[2] = predictImpl<Average, Width, 2>;
  out[3] = predictImpl<Average, Width, 3>;
}

// This target's kernels, picked once (a dispatch per block would cost more than a small block).
McKernels mcTable() {
  McKernels k{};
  fill<false, 8>(k.predict[0][0]);
  fill<false, 16>(k.predict[0][1]);
  fill<true, 8>(k.predict[1][0]);
  fill<true, 16>(k.predict[1][1]);
  k.name = "highway";
  return k;
}
#else
McKernels mcTable() {
  return scalarMcKernels();
}
#endif

}  // namespace vbim::ipu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vbim::ipu {

HWY_EXPORT(mcTable);

McKernels simdMcKernelsOfCurrentTarget() {
  return HWY_DYNAMIC_DISPATCH(mcTable)();
}

const McKernels& simdMcKernels() {
  static const McKernels k = simdMcKernelsOfCurrentTarget();
  return k;
}

}  // namespace vbim::ipu
#endif
