// Test support: libmpeg2 0.5.1's C decoder (acceleration off: the reference `mpeg2dec -c` runs) on
// an elementary stream, frames in display order.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/image.hpp"

namespace vbim::ipu::testing {

std::vector<Yuv420Image> decodeWithLibmpeg2(const std::vector<std::uint8_t>& es);

}  // namespace vbim::ipu::testing
