// Reassembles the pictures of one video stream from its PES payloads. A picture is the run of
// elementary-stream bytes from the sequence header (or GOP or picture header) that precedes a
// picture start code, up to the next such header after it (ISO/IEC 13818-2 §6.2). Start codes are
// found across PES and pack boundaries. Reading starts, and restarts after reset(), at a sequence
// header. A picture is complete when the next one begins, at a
// sequence end code, or at finish().
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vbim::streams {

struct Picture {
  std::uint8_t streamId = 0;
  std::uint32_t firstSector = 0;       // sector holding the picture's first byte
  std::uint32_t lastSector = 0;        // sector holding its last byte
  std::uint64_t byteOffset = 0;        // file offset of its first byte
  std::optional<std::int64_t> pts;     // of the PES packet in which its first byte begins, if unused
  std::optional<std::uint32_t> frame;  // global frame number, when a descriptor identified it
  bool damaged = false;                // disagrees with the descriptor index (size or CRC)
  std::vector<std::uint8_t> data;      // sequence header .. last slice
};

// The largest picture accepted: the MPEG-2 Main Profile @ Main Level VBV buffer, 1835008 bits
// (13818-2 table 8-13). A longer run without a picture boundary is damage; it also bounds memory.
inline constexpr std::size_t kMaxPictureBytes = 1835008 / 8;

class PictureAssembler {
 public:
  explicit PictureAssembler(std::uint8_t streamId) : streamId_(streamId) {}

  // Appends one PES payload that starts at `byteOffset` of the file, in `sector`. Completed pictures
  // are appended to `out`. Returns false if the picture in progress grew past kMaxPictureBytes and was
  // dropped.
  bool append(std::span<const std::uint8_t> payload, std::uint32_t sector, std::uint64_t byteOffset,
              std::optional<std::int64_t> pts, std::vector<Picture>& out);
  // Drops the picture in progress (after damage or a seek); true if one was under way.
  bool reset();
  // End of data: the picture in progress is complete if it has a picture start code.
  void finish(std::vector<Picture>& out);

  std::uint64_t discardedBytes() const { return discarded_; }

 private:
  // Where a PES payload landed in buf_.
  struct Segment {
    std::int64_t pos;
    std::uint32_t sector;
    std::uint64_t byteOffset;
    std::optional<std::int64_t> pts;
    bool ptsUsed = false;
  };
  void onStartCode(std::size_t pos, std::uint8_t code, std::vector<Picture>& out);
  void emit(std::size_t end, std::vector<Picture>& out);
  void drop(std::size_t count);
  Segment& segmentAt(std::size_t pos);
  void takePts(std::size_t pos);

  std::uint8_t streamId_;
  std::vector<std::uint8_t> buf_;
  std::vector<Segment> segments_;
  std::size_t scanFrom_ = 0;
  bool synced_ = false;       // buf_ starts at a picture's first header
  bool seenPicture_ = false;  // buf_ holds a picture start code
  std::optional<std::int64_t> pts_;
  std::uint64_t discarded_ = 0;
};

}  // namespace vbim::streams
