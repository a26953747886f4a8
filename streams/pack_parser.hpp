// Parses one pack: the pack header, an optional system header, then PES packets (ISO/IEC 13818-1
// §2.5.3; MPEG-1 system streams: ISO/IEC 11172-1 §2.4.3). Payloads are views into the bytes given.
//
// Two layouts, one set of syntax rules:
// - parsePack: a VBIM sector. The pack is exactly 2048 bytes (one DVD sector), MPEG-2, and its
//   packets use it up exactly. This is what the EE demux receives.
// - parsePackAt: a pack of any program stream held in memory: MPEG-2 or MPEG-1 pack headers, packs
//   of any size (ffmpeg's `-packetsize`, MPEG-1 system streams that send many packets after one pack
//   header), MPEG-1 or MPEG-2 PES headers. The pack ends where the next pack header begins, after the
//   program end code, or at the end of the data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "streams/stream_error.hpp"

namespace vbim::streams {

struct PesPacket {
  std::uint8_t streamId = 0;
  std::size_t offset = 0;                 // of its 00 00 01 in the bytes parsed (the sector, or the data)
  std::optional<std::int64_t> pts;        // 90 kHz, when the header carries one
  std::size_t payloadOffset = 0;          // first payload byte in the bytes parsed
  std::span<const std::uint8_t> payload;  // the bytes after the PES header
};

struct ParsedPack {
  std::int64_t scr27MHz = 0;  // system clock reference, 27 MHz units
  std::uint32_t muxRate = 0;  // program_mux_rate, units of 50 bytes/s
  bool mpeg1 = false;         // an MPEG-1 (ISO/IEC 11172-1) pack header
  bool hasSystemHeader = false;
  bool hasEndCode = false;  // MPEG_program_end_code (in a sector, the rest of the pack is ignored)
  std::size_t size = 0;     // bytes the pack occupies, up to and including an end code
  std::vector<PesPacket> packets;
};

// Parses `sector` (must be 2048 bytes). Returns the defect when the pack is malformed; `out` is then
// partial and must not be used. `lsn` is only used to place the error.
std::optional<StreamError> parsePack(std::span<const std::uint8_t> sector, std::uint32_t lsn, ParsedPack& out);

// Parses the pack that begins at `pos` of `data` (a whole program stream, data[0] being byte 0 of
// the file). Offsets in `out` and in the error are offsets in `data`; an error's sector is the
// 2048-byte sector its byte falls in. On a defect, `out.packets` holds the packets before it, and a
// PES packet cut by the end of the data (ErrorKind::Truncated) is kept with the payload that is there.
std::optional<StreamError> parsePackAt(std::span<const std::uint8_t> data, std::size_t pos, ParsedPack& out);

}  // namespace vbim::streams
