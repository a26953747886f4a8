#include "gs/image_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace vbim::gs {

ByteDifference compareRectScalar(const std::uint8_t* a, std::size_t aStride, const std::uint8_t* b, std::size_t bStride,
                                 std::size_t bytes, std::size_t rows) {
  int mx = 0;
  std::int64_t sum = 0;
  for (std::size_t y = 0; y < rows; ++y, a += aStride, b += bStride) {
    for (std::size_t i = 0; i < bytes; ++i) {
      const int d = std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
      mx = std::max(mx, d);
      sum += d;
    }
  }
  return ByteDifference{mx, sum};
}

}  // namespace vbim::gs
