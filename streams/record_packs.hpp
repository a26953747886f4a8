// How a stream was authored (terrain, cell size, day span, frame times, lighting settings, vbim
// version), carried in the stream itself so that tools downstream (`vbim info`, `vbim play`,
// `vbim render`) need no option repeated. The record is text (JSON, written by the authoring side)
// in private_stream_2 (0xBF) packets with the magic `VBIA`, in packs appended after the stream's last
// video sector (the descriptor's total_sectors): every sector a player reads, and the descriptor,
// are unchanged, and readers that do not know the record skip it as they skip any private_stream_2
// packet that is not a VBIM chunk. Byte layout: docs/stream-format.md, "The authoring record".
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "streams/descriptor_packs.hpp"

namespace vbim::streams {

inline constexpr std::uint8_t kAuthoringMagic[4] = {'V', 'B', 'I', 'A'};

// Appends the record's packs to a finished stream (whole 2048-byte packs, its last pack giving the
// SCR and mux rate the new packs continue from). Throws std::invalid_argument for a stream that is
// not whole packs or a record too large for 65535 packs.
void appendAuthoringRecord(std::vector<std::uint8_t>& stream, std::string_view text);

// Packs needed for a record of `textBytes`.
std::size_t authoringRecordSectors(std::size_t textBytes);

// The record in `sectors` (whole 2048-byte sectors, e.g. those after the descriptor's total_sectors),
// or nullopt when they hold none or only part of one (a truncated file).
std::optional<std::string> findAuthoringRecord(std::span<const std::uint8_t> sectors);

}  // namespace vbim::streams
