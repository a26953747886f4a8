// The playback descriptor: what the player needs beyond the video (game-time frame rate, loop point,
// weather variants, and a frame -> sector index per stream). It travels in private_stream_2 (0xBF)
// packets in the first packs of the stream, which standard players skip. Byte layout:
// docs/stream-format.md, "The playback descriptor".
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "streams/picture_header.hpp"

namespace vbim::streams {

struct Rational {
  std::uint32_t num = 0;
  std::uint32_t den = 1;
  double value() const { return den ? static_cast<double>(num) / den : 0.0; }
  bool operator==(const Rational&) const = default;
};

enum class StreamRole : std::uint8_t { Lightmap = 0, Sky = 1 };

struct StreamEntry {
  std::uint8_t id = 0;  // 0xE0 lightmap, 0xE1 sky
  StreamRole role = StreamRole::Lightmap;
  std::uint16_t width = 0;
  std::uint16_t height = 0;
  bool operator==(const StreamEntry&) const = default;
};

struct Variant {
  std::string name;               // at most kMaxVariantName bytes of UTF-8
  std::uint32_t firstFrame = 0;   // global frame number of its frame 0
  std::uint32_t firstSector = 0;  // first sector holding data of this variant
  bool operator==(const Variant&) const = default;
};

struct IndexEntry {
  std::uint32_t sector = 0;  // sector holding the picture's first byte (its first header)
  std::uint16_t offset = 0;  // position of that byte in the 2048-byte pack
  std::uint32_t bytes = 0;   // elementary-stream bytes of the picture
  std::uint32_t crc = 0;     // CRC-32 of those bytes
  // Version 2 (streams with P or B pictures); a version 1 stream's pictures are all GOP-starting I
  // pictures of closed GOPs.
  PictureType type = PictureType::I;
  bool gopStart = true;   // a sequence and GOP header precede it: decoding can start here
  bool closedGop = true;  // that GOP header's closed_gop flag (gopStart only)
  bool operator==(const IndexEntry&) const = default;
};

struct Descriptor {
  // Version 1: every picture intra (written for intra-only streams, byte for byte as before).
  // Version 2: P and B pictures; index entries carry the picture type and GOP flags.
  static constexpr std::uint16_t kVersionIntra = 1;
  static constexpr std::uint16_t kVersion = 2;
  static constexpr std::size_t kHeaderBytes = 48;
  static constexpr std::size_t kStreamBytes = 8;
  static constexpr std::size_t kVariantBytes = 32;
  static constexpr std::size_t kMaxVariantName = 23;
  static constexpr std::size_t kEntryBytes = 16;

  Rational gameFps;  // stream frames per second of game time
  std::uint32_t framesPerVariant = 0;
  std::uint32_t loopFrame = 0;    // frame playback returns to after the last one
  std::int64_t firstPts = 0;      // 90 kHz PTS of global frame 0 in the container
  std::uint32_t ptsPerFrame = 0;  // 90 kHz ticks between consecutive global frames
  std::uint32_t descriptorSectors = 0;
  std::uint32_t totalSectors = 0;
  std::vector<StreamEntry> streams;
  std::vector<Variant> variants;
  std::vector<std::vector<IndexEntry>> index;  // [stream][global frame]

  std::uint32_t totalFrames() const { return framesPerVariant * static_cast<std::uint32_t>(variants.size()); }
  // Position of `id` in streams, or -1.
  int streamIndex(std::uint8_t id) const;
  // The global frame a PTS belongs to, if it is one of this stream's frame times.
  std::optional<std::uint32_t> frameOfPts(std::int64_t pts) const;
  // True when every indexed picture is an I picture (written as version 1).
  bool intraOnly() const;
  // Where decoding must start to show global frame g of stream `s` (its index position) from a cold
  // start (seek, loop, branch, damage): the nearest frame at or before g, in g's variant, whose
  // picture starts a GOP. Decoding every picture of the stream in stream order from that picture's
  // sector gives frame g once the pictures shown before it are output.
  std::uint32_t resumeFrame(std::size_t s, std::uint32_t g) const;
  // Variant index of a global frame.
  std::size_t variantOf(std::uint32_t globalFrame) const { return globalFrame / framesPerVariant; }
  // Checks the fields against each other; returns what is wrong, or empty.
  std::string validate() const;
  bool operator==(const Descriptor&) const = default;
};

std::size_t serializedSize(std::size_t streams, std::size_t variants, std::size_t framesPerVariant);
// Big-endian body with its CRC filled in. Call validate() first; throws std::invalid_argument if invalid.
std::vector<std::uint8_t> serialize(const Descriptor& d);

struct DescriptorParse {
  std::optional<Descriptor> descriptor;
  std::size_t errorOffset = 0;  // byte of the body where the problem was found
  std::string error;
};
DescriptorParse parseDescriptor(std::span<const std::uint8_t> body);

}  // namespace vbim::streams
