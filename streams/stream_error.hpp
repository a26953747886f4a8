// A defect found while reading a stream: a value, not an exception, so a player can count damage
// and continue with the next sector.
#pragma once

#include <cstdint>
#include <string>

namespace vbim::streams {

enum class ErrorKind {
  ShortSector,      // fewer than 2048 bytes (truncated file)
  BadPackHeader,    // no 00 00 01 BA, MPEG-1 pack, missing marker bits
  BadPes,           // PES start code, length or header not as 13818-1 requires
  PackOverrun,      // a PES packet runs past the end of its 2048-byte pack
  PictureDropped,   // a partly assembled picture lost to damage or a sector gap
  PictureMismatch,  // an assembled picture disagrees with the descriptor index (size or CRC)
  BadDescriptor,    // the playback descriptor is malformed
  Truncated,        // a pack or packet of a program stream read whole is cut by the end of the data
};

const char* toString(ErrorKind kind);

struct StreamError {
  ErrorKind kind{};
  std::uint64_t byteOffset = 0;  // in the stream file (sector * 2048 + offset in the pack)
  std::uint32_t sector = 0;      // sector number (LSN relative to the start of the stream file); for
                                 // a stream of packs of any size, the 2048-byte sector of byteOffset
  std::string message;           // what was found and what was expected

  // "sector 12 (byte 24590): PES packet of 2100 bytes overruns the pack by 66 bytes"
  std::string describe() const;
};

}  // namespace vbim::streams
