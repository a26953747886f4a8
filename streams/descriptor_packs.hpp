// How the descriptor body is carried: split into chunks, one private_stream_2 (0xBF) PES packet per
// pack, each pack exactly 2048 bytes, placed in front of the muxed video (docs/stream-format.md).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vbim::streams {

inline constexpr std::uint8_t kChunkMagic[4] = {'V', 'B', 'I', 'M'};
using ChunkMagic = std::span<const std::uint8_t, 4>;
inline constexpr std::size_t kChunkHeaderBytes = 12;

struct DescriptorChunk {
  std::uint16_t index = 0;
  std::uint16_t count = 0;
  std::span<const std::uint8_t> data;
};

// The chunk in a private_stream_2 payload, or nullopt if the payload is not a VBIM chunk (e.g. a
// DVD navigation packet) or its declared length does not fit.
std::optional<DescriptorChunk> parseDescriptorChunk(std::span<const std::uint8_t> payload,
                                                    ChunkMagic magic = ChunkMagic(kChunkMagic));

// Number of packs needed for a body of `bodyBytes`, the first pack also holding `systemHeaderBytes`.
std::size_t descriptorPackCount(std::size_t bodyBytes, std::size_t systemHeaderBytes);

// The packs, concatenated (descriptorPackCount * 2048 bytes). `systemHeader` (a whole 00 00 01 BB
// header, may be empty) is copied into the first pack, as 13818-1 §2.5.3.5 wants it in the first
// pack of the stream. Pack i carries SCR scr27MHz[i].
std::vector<std::uint8_t> makeDescriptorPacks(std::span<const std::uint8_t> body,
                                              std::span<const std::uint8_t> systemHeader, std::uint32_t muxRate,
                                              std::span<const std::int64_t> scr27MHz,
                                              ChunkMagic magic = ChunkMagic(kChunkMagic));

// A 14-byte MPEG-2 pack header with no stuffing (13818-1 §2.5.3.3).
void writePackHeader(std::uint8_t* out, std::int64_t scr27MHz, std::uint32_t muxRate);

}  // namespace vbim::streams
