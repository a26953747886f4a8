// Reads a whole stream (file or bytes) through the Demuxer and summarises it: what `vbim info`
// prints and what the author uses to build the index.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "streams/demuxer.hpp"
#include "streams/picture_header.hpp"

namespace vbim::streams {

struct PictureRecord {
  std::uint8_t streamId = 0;
  std::uint32_t firstSector = 0;
  std::uint32_t lastSector = 0;
  std::uint64_t byteOffset = 0;
  std::uint32_t bytes = 0;
  std::uint32_t crc = 0;
  std::optional<std::int64_t> pts;
  std::optional<std::uint32_t> frame;
  bool damaged = false;
  std::optional<PictureHeaderInfo> header;  // type and GOP flags, when the picture header is readable
};

struct StreamScan {
  std::uint64_t fileBytes = 0;
  std::uint32_t sectors = 0;  // whole sectors (a trailing partial one is counted in errors)
  bool every2048 = false;     // the size is a multiple of 2048 and no pack is malformed
  std::uint32_t muxRate = 0;  // program_mux_rate of the first good pack (50 B/s units)
  std::optional<Descriptor> descriptor;
  std::vector<StreamError> errors;
  DemuxStats stats;
  std::vector<PictureRecord> pictures;  // in completion order
};

StreamScan scanStream(std::span<const std::uint8_t> bytes);
// Throws std::runtime_error naming the file if it cannot be opened or read.
StreamScan scanStreamFile(const std::filesystem::path& path);

struct Summary {
  double min = 0, mean = 0, max = 0;
};

// Pictures of one picture_coding_type.
struct TypeReport {
  std::size_t pictures = 0;
  Summary bytes;
};

// One GOP shape: the picture types of a GOP in display order (temporal_reference), how many GOPs have it.
struct GopShape {
  std::string pattern;  // e.g. "IBBPBBPBBPBP"
  std::size_t count = 0;
};

struct StreamReport {
  std::uint8_t id = 0;
  std::size_t pictures = 0;
  Summary bytes;        // elementary-stream bytes per picture
  Summary spanSectors;  // sectors a picture's bytes touch (last - first + 1)
  Summary stepSectors;  // sectors from one picture's start to the next (all streams' data included)
  // The worst run: the most sectors read to advance `runFrames` consecutive frames (one second of game
  // time), starting at frame `runStart`.
  std::uint32_t runFrames = 0;
  std::uint32_t runSectors = 0;
  std::uint32_t runStart = 0;
  // Read rate needed over time: bits per second of game time for each group of `bucketFrames` frames.
  std::uint32_t bucketFrames = 0;
  std::vector<double> bitsPerSecond;
  // Picture types (index 0 I, 1 P, 2 B) and pictures whose header could not be read.
  std::array<TypeReport, 3> types;
  std::size_t unknownType = 0;
  // GOPs in stream order, split at GOP headers (pictures before the first one are not counted).
  std::size_t gops = 0, closedGops = 0;
  Summary gopPictures;           // pictures per GOP
  std::vector<GopShape> shapes;  // distinct shapes, in order of first appearance
};

// One report per video stream found. `gameFps` (from the descriptor, else the caller's guess) sets
// the run length and the time base of the bitrate.
std::vector<StreamReport> summarise(const StreamScan& scan, double gameFps, std::uint32_t bucketFrames);

}  // namespace vbim::streams
