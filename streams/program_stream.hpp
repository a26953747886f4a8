// Reads a whole program stream held in memory, pack after pack: MPEG-2 program streams and MPEG-1
// system streams with packs of any size, as ffmpeg (`-f vob`, `-f mpeg`, any `-packetsize`) and other
// muxers write them, VBIM streams included. The syntax is parsePackAt's (streams/pack_parser.hpp);
// this adds the walk and the recovery. The EE demux reads VBIM streams sector by sector instead
// (streams/demuxer.hpp).
//
// Damage does not stop it: a malformed pack is recorded as a defect (kind, byte offset), the packets
// read before the defect are still returned, and reading resumes at the next pack start code. A pack
// or packet cut by the end of the data ends the reading, with what there is of the cut packet.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "streams/pack_parser.hpp"
#include "streams/stream_error.hpp"

namespace vbim::streams {

class ProgramStreamReader {
 public:
  // `data` must outlive the reader and the packs it returns (payloads are views into it).
  explicit ProgramStreamReader(std::span<const std::uint8_t> data) : data_(data) {}

  // The next pack (or the packets of a damaged one before its defect); false at the end of the data
  // or after the program end code.
  bool next(ParsedPack& pack);
  // Where the pack last returned begins in the data.
  std::size_t packOffset() const { return packOffset_; }
  const std::vector<StreamError>& defects() const { return defects_; }

 private:
  std::size_t nextPackStart(std::size_t from) const;

  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
  std::size_t packOffset_ = 0;
  bool ended_ = false;
  std::vector<StreamError> defects_;
};

}  // namespace vbim::streams
