// The per-byte difference of two images, or of the same rectangle of two images: the largest
// |a - b| and the sum of |a - b| over every byte (alpha included). The lag metric is built on it
// (gs/lag_meter.hpp). The scalar function here is the reference; gs/simd/compare_simd.hpp has a
// SIMD one with the same results, injected through BlendKernels::compareRect (gs/blend.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace vbim::gs {

struct ByteDifference {
  int max = 0;           // largest per-byte |a - b|
  std::int64_t sum = 0;  // sum over every byte
};

// Over `rows` rows of `bytes` bytes each; a's rows are aStride bytes apart, b's bStride.
using CompareRectFn = ByteDifference (*)(const std::uint8_t* a, std::size_t aStride, const std::uint8_t* b,
                                         std::size_t bStride, std::size_t bytes, std::size_t rows);

ByteDifference compareRectScalar(const std::uint8_t* a, std::size_t aStride, const std::uint8_t* b, std::size_t bStride,
                                 std::size_t bytes, std::size_t rows);

}  // namespace vbim::gs
