// Start codes (ISO/IEC 13818-2 §5.3): the prefix 00 00 01 before every header and slice. Finding
// them is the serial part of slice-parallel decode (the slices are found before they are handed
// out), so it is made fast.
#pragma once

#include <cstddef>
#include <cstdint>

namespace vbim::ipu {

// Position of the first prefix 00 00 01 at or after `from` in d[0, n), or n.
std::size_t findStartCode(const std::uint8_t* d, std::size_t n, std::size_t from);

}  // namespace vbim::ipu
