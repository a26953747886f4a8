// What `vbim info` and the author read from a picture's own bytes (one reassembled picture, from its
// sequence/GOP/picture header to its last slice): the picture header's type and temporal reference
// and, when a GOP header precedes it, that header's flags (ISO/IEC 13818-2 §6.2.2.6, §6.2.3).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

namespace vbim::streams {

// picture_coding_type (13818-2 table 6-12).
enum class PictureType : std::uint8_t { I = 1, P = 2, B = 3 };

struct PictureHeaderInfo {
  PictureType type = PictureType::I;
  std::uint16_t temporalReference = 0;  // display position within its GOP (10 bits)
  bool gopHeader = false;               // a group_of_pictures header precedes the picture
  bool closedGop = false;               // that header's closed_gop flag
  bool brokenLink = false;              // that header's broken_link flag
};

// Reads the first picture header in `data` (and a GOP header before it). Empty when there is no
// whole picture header or its coding type is not I, P or B (a D picture, or damage).
std::optional<PictureHeaderInfo> readPictureHeader(std::span<const std::uint8_t> data);

// "I", "P" or "B".
const char* pictureTypeName(PictureType t);

}  // namespace vbim::streams
