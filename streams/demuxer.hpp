// The stream reader: fed 2048-byte sectors with their sector numbers, the way the EE demux receives
// them from the IOP ring. It parses each pack, skips padding and unknown streams, reassembles the
// pictures of the lightmap (0xE0) and sky (0xE1) streams, collects the playback descriptor from the
// private_stream_2 packs and checks each picture against the descriptor's index.
//
// Sector numbers are counted from the start of the stream file (sector 0 holds the first descriptor
// pack), as the descriptor index is.
//
// Damage does not stop it: a malformed pack is reported (kind, byte offset, sector), the pictures in
// progress are dropped (reported too), and reading continues with the next sector. A jump in the
// sector numbers (a seek) also drops the pictures in progress.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "streams/descriptor.hpp"
#include "streams/pack_parser.hpp"
#include "streams/picture_assembler.hpp"
#include "streams/stream_error.hpp"

namespace vbim::streams {

struct DemuxStats {
  std::uint64_t sectors = 0;
  std::uint64_t badSectors = 0;
  std::uint64_t pictures = 0;
  std::uint64_t droppedPictures = 0;
  std::uint64_t damagedPictures = 0;
  std::uint64_t paddingBytes = 0;
  std::uint64_t skippedPackets = 0;  // PES packets of streams the reader does not use
  std::uint64_t systemHeaders = 0;
  std::uint64_t sectorGaps = 0;  // sector numbers that did not follow the previous one
};

class Demuxer {
 public:
  Demuxer();

  // Feeds one sector. Returns how many defects it added to errors() (0 for a good sector).
  std::size_t feed(std::span<const std::uint8_t> sector, std::uint32_t lsn);
  // End of data: completes the pictures in progress.
  void finish();
  // The caller moved the read position (seek, branch): drop the pictures in progress silently.
  void seek();
  // Uses a descriptor read earlier (e.g. when reading starts after the descriptor packs).
  void setDescriptor(Descriptor d);

  // Completed pictures, in the order they completed. The caller may move them out and clear().
  std::vector<Picture>& pictures() { return pictures_; }
  const std::optional<Descriptor>& descriptor() const { return descriptor_; }
  const std::vector<StreamError>& errors() const { return errors_; }
  const DemuxStats& stats() const { return stats_; }
  // The last good pack (SCR, mux rate), for inspection.
  const ParsedPack& lastPack() const { return pack_; }

 private:
  void dropInProgress(std::uint32_t lsn, const char* why);
  void onDescriptorChunk(std::span<const std::uint8_t> payload, std::uint32_t lsn, std::uint64_t offset);
  void indexPositions();
  void identify(std::size_t firstNew);

  std::array<PictureAssembler, 2> assemblers_;
  std::vector<Picture> pictures_;
  std::vector<StreamError> errors_;
  DemuxStats stats_;
  ParsedPack pack_;
  std::optional<std::uint32_t> expectedLsn_;
  std::optional<Descriptor> descriptor_;
  std::vector<std::vector<std::uint8_t>> chunks_;  // descriptor chunks collected so far
  bool descriptorFailed_ = false;
  // Per stream: file byte offset of each indexed picture -> global frame.
  std::array<std::unordered_map<std::uint64_t, std::uint32_t>, 2> positions_;
};

}  // namespace vbim::streams
