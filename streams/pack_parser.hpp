// Parses one 2048-byte pack: the MPEG-2 pack header, an optional system header, then PES packets
// until the pack is exactly used up (ISO/IEC 13818-1 §2.5.3). Payloads are views into the sector.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "streams/stream_error.hpp"

namespace vbim::streams {

struct PesPacket {
  std::uint8_t streamId = 0;
  std::uint32_t offset = 0;               // of its 00 00 01 in the pack
  std::optional<std::int64_t> pts;        // 90 kHz, when the header carries one
  std::uint32_t payloadOffset = 0;        // first payload byte in the pack
  std::span<const std::uint8_t> payload;  // the bytes after the PES header
};

struct ParsedPack {
  std::int64_t scr27MHz = 0;  // system clock reference, 27 MHz units
  std::uint32_t muxRate = 0;  // program_mux_rate, units of 50 bytes/s
  bool hasSystemHeader = false;
  bool hasEndCode = false;  // MPEG_program_end_code (rest of the pack ignored)
  std::vector<PesPacket> packets;
};

// Parses `sector` (must be 2048 bytes). Returns the defect when the pack is malformed; `out` is then
// partial and must not be used. `lsn` is only used to place the error.
std::optional<StreamError> parsePack(std::span<const std::uint8_t> sector, std::uint32_t lsn, ParsedPack& out);

}  // namespace vbim::streams
