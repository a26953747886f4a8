#include "ipu/elementary_stream.hpp"

#include <cstdint>

#include "ipu/headers.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {

std::vector<AccessUnit> splitAccessUnits(std::span<const std::uint8_t> es) {
  std::vector<AccessUnit> units;
  const std::uint8_t* d = es.data();
  const std::size_t n = es.size();
  std::size_t unitBegin = 0;
  bool sawPicture = false;
  std::size_t headerStart = SIZE_MAX;  // first sequence/GOP header after the current picture's data
  for (std::size_t i = findStartCode(d, n, 0); i + 3 < n; i = findStartCode(d, n, i + 3)) {
    const std::uint8_t code = d[i + 3];
    if (code == kPictureStartCode) {
      if (sawPicture) {
        const std::size_t cut = headerStart != SIZE_MAX ? headerStart : i;
        units.push_back({unitBegin, cut - unitBegin});
        unitBegin = cut;
      }
      sawPicture = true;
      headerStart = SIZE_MAX;
    } else if (code == kSequenceHeaderCode || code == kGroupStartCode) {
      if (sawPicture && headerStart == SIZE_MAX) headerStart = i;
    }
  }
  if (n > unitBegin) units.push_back({unitBegin, n - unitBegin});
  return units;
}

}  // namespace vbim::ipu
