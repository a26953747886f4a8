// Highway kernel for the per-byte difference: |a - b| per byte as the OR of the two saturated
// differences (one of them is zero), the maximum kept per lane, the sum by SumsOf8 (PSADBW on x86:
// eight bytes into one 64-bit lane, so no lane can overflow). Three to four vector operations per
// vector of bytes against the reference's widening per byte; the last bytes of a row that do not
// fill a vector go through the scalar reference.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gs/simd/compare_simd.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include <algorithm>

#include "gs/image_compare.hpp"

HWY_BEFORE_NAMESPACE();
namespace vbim::gs::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

ByteDifference compareRectHere(const std::uint8_t* HWY_RESTRICT a, std::size_t aStride,
                               const std::uint8_t* HWY_RESTRICT b, std::size_t bStride, std::size_t bytes,
                               std::size_t rows) {
#if HWY_TARGET == HWY_SCALAR
  return compareRectScalar(a, aStride, b, bStride, bytes, rows);  // one lane: the reference itself
#else
  const hn::ScalableTag<std::uint8_t> d8;
  const hn::Repartition<std::uint64_t, decltype(d8)> d64;
  const std::size_t step = hn::Lanes(d8);
  auto maxAcc = hn::Zero(d8);
  auto sumAcc = hn::Zero(d64);
  ByteDifference tail;
  for (std::size_t y = 0; y < rows; ++y, a += aStride, b += bStride) {
    std::size_t i = 0;
    for (; i + step <= bytes; i += step) {
      const auto va = hn::LoadU(d8, a + i);
      const auto vb = hn::LoadU(d8, b + i);
      const auto diff = hn::Or(hn::SaturatedSub(va, vb), hn::SaturatedSub(vb, va));
      maxAcc = hn::Max(maxAcc, diff);
      sumAcc = hn::Add(sumAcc, hn::SumsOf8(diff));
    }
    if (i < bytes) {
      const ByteDifference t = compareRectScalar(a + i, 0, b + i, 0, bytes - i, 1);
      tail.max = std::max(tail.max, t.max);
      tail.sum += t.sum;
    }
  }
  // Each 64-bit lane holds at most 255 * 8 per vector loaded: no overflow below 2^53 bytes.
  std::uint8_t maxLanes[256];  // >= the widest vector of any target
  hn::StoreU(maxAcc, d8, maxLanes);
  ByteDifference r = tail;
  for (std::size_t k = 0; k < step; ++k) r.max = std::max<int>(r.max, maxLanes[k]);
  r.sum += static_cast<std::int64_t>(hn::GetLane(hn::SumOfLanes(d64, sumAcc)));
  return r;
#endif
}

}  // namespace vbim::gs::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "gs/simd/compare_simd.hpp"
#include "runtime/simd/targets.hpp"

namespace vbim::gs::simd {

VBIM_SIMD_EXPORT(compareRectHere);

ByteDifference compareRect(const std::uint8_t* a, std::size_t aStride, const std::uint8_t* b, std::size_t bStride,
                           std::size_t bytes, std::size_t rows) {
  return VBIM_SIMD_DISPATCH(compareRectHere)(a, aStride, b, bStride, bytes, rows);
}

}  // namespace vbim::gs::simd
#endif  // HWY_ONCE
