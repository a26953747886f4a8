// The per-byte difference of two image rectangles (gs/image_compare.hpp) with Highway's run-time
// dispatch, in vbim_gs_simd beside the blend kernels: simd::kernels().compareRect is this function.
// The tests prove every compiled target equal to compareRectScalar.
#pragma once

#include "gs/image_compare.hpp"

namespace vbim::gs::simd {

ByteDifference compareRect(const std::uint8_t* a, std::size_t aStride, const std::uint8_t* b, std::size_t bStride,
                           std::size_t bytes, std::size_t rows);

}  // namespace vbim::gs::simd
