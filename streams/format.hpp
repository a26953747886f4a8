// Constants of the VBIM stream format: an MPEG-2 Program Stream (ISO/IEC 13818-1 §2.5) whose packs are
// exactly one 2048-byte DVD sector each. Byte-by-byte description: docs/stream-format.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vbim::streams {

// One pack per DVD user sector of 2048 bytes (docs/hardware.md#dvd-drive).
inline constexpr std::size_t kSectorBytes = 2048;

// Start code values (the byte after 00 00 01), ISO/IEC 13818-1 table 2-18 and 13818-2 table 6-1.
inline constexpr std::uint8_t kPackStartCode = 0xBA;
inline constexpr std::uint8_t kSystemHeaderStartCode = 0xBB;
inline constexpr std::uint8_t kProgramEndCode = 0xB9;
inline constexpr std::uint8_t kPaddingStream = 0xBE;
inline constexpr std::uint8_t kPrivateStream1 = 0xBD;
inline constexpr std::uint8_t kPrivateStream2 = 0xBF;

// The two video streams of a VBIM stream.
inline constexpr std::uint8_t kLightmapStream = 0xE0;
inline constexpr std::uint8_t kSkyStream = 0xE1;

// Video elementary stream start codes (13818-2 table 6-1).
inline constexpr std::uint8_t kPictureStartCode = 0x00;
inline constexpr std::uint8_t kSequenceHeaderCode = 0xB3;
inline constexpr std::uint8_t kSequenceEndCode = 0xB7;
inline constexpr std::uint8_t kGroupStartCode = 0xB8;

// Pack header size without stuffing (13818-1 §2.5.3.3): start code + 10 bytes.
inline constexpr std::size_t kPackHeaderBytes = 14;
// An MPEG-1 system stream's pack header (ISO/IEC 11172-1 §2.4.3.2): start code + 8 bytes, no stuffing.
inline constexpr std::size_t kMpeg1PackHeaderBytes = 12;

// The 90 kHz clock of PTS values.
inline constexpr std::int64_t kPtsHz = 90000;

inline bool isVideoStream(std::uint8_t id) {
  return id >= 0xE0 && id <= 0xEF;
}

// A PES stream id as `vbim info` and `vbim decode` name it: "0xE0".
inline std::string hexId(std::uint8_t id) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  return std::string("0x") + kHex[(id >> 4) & 15] + kHex[id & 15];
}

}  // namespace vbim::streams
