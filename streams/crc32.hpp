// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320, as zlib's crc32). Protects the playback
// descriptor and each indexed picture.
#pragma once

#include <cstdint>
#include <span>

namespace vbim::streams {

std::uint32_t crc32(std::span<const std::uint8_t> data, std::uint32_t previous = 0);

}  // namespace vbim::streams
