// Splits an MPEG-1/2 video elementary stream into access units: each unit is one picture with the
// sequence, GOP and extension headers that precede it, so Decoder::decode() gets one picture at a
// time (ISO/IEC 13818-2 §6.2.1 start codes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vbim::ipu {

struct AccessUnit {
  std::size_t offset = 0;  // in the elementary stream
  std::size_t size = 0;
};

std::vector<AccessUnit> splitAccessUnits(std::span<const std::uint8_t> es);

}  // namespace vbim::ipu
