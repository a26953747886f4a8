#include "streams/picture_header.hpp"

#include "streams/format.hpp"

namespace vbim::streams {

std::optional<PictureHeaderInfo> readPictureHeader(std::span<const std::uint8_t> data) {
  PictureHeaderInfo info;
  for (std::size_t i = 0; i + 3 < data.size(); ++i) {
    if (data[i] != 0 || data[i + 1] != 0 || data[i + 2] != 1) continue;
    const std::uint8_t code = data[i + 3];
    if (code == kGroupStartCode) {
      // time_code (25 bits), closed_gop, broken_link: bits 25 and 26 after the start code.
      if (i + 8 > data.size()) return std::nullopt;
      info.gopHeader = true;
      info.closedGop = (data[i + 7] & 0x40) != 0;
      info.brokenLink = (data[i + 7] & 0x20) != 0;
    } else if (code == kPictureStartCode) {
      // temporal_reference (10 bits), picture_coding_type (3 bits).
      if (i + 6 > data.size()) return std::nullopt;
      info.temporalReference = static_cast<std::uint16_t>((data[i + 4] << 2) | (data[i + 5] >> 6));
      const int type = (data[i + 5] >> 3) & 7;
      if (type < 1 || type > 3) return std::nullopt;
      info.type = static_cast<PictureType>(type);
      return info;
    }
  }
  return std::nullopt;
}

const char* pictureTypeName(PictureType t) {
  switch (t) {
    case PictureType::I:
      return "I";
    case PictureType::P:
      return "P";
    case PictureType::B:
      return "B";
  }
  return "?";
}

}  // namespace vbim::streams
