// What the decoder tells its caller about one picture: what was decoded, what was concealed and
// where each problem was found (byte offset in the input, macroblock column and row).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vbim::ipu {

enum class IssueKind : std::uint8_t {
  kBadVlc,                   // a bit pattern that is no code of the table in force
  kTruncatedSlice,           // slice data ended inside a macroblock
  kCoefficientOverrun,       // run/level past the 64th coefficient of a block
  kBadMacroblockAddress,     // increment past the row end, or a skip in an intra picture
  kBadSlicePosition,         // slice_vertical_position outside the picture
  kMissingMacroblocks,       // macroblocks no slice covered (kept from the previous picture)
  kMissingSequenceHeader,    // picture data before any sequence header
  kMissingPictureHeader,     // slice data before any picture header
  kMissingCodingExtension,   // MPEG-2 sequence but the picture has no picture coding extension
  kBadHeader,                // a header or extension too short or with invalid values
  kAbsurdSize,               // picture size zero or beyond the configured limit
  kUnsupportedChromaFormat,  // 4:2:2 or 4:4:4 (the IPU decodes 4:2:0 only)
  kUnsupportedPictureType,   // a D picture (MPEG-1 DC-only pictures are not decoded)
  kBadMotionVector,          // a motion vector pointing outside the reference frame (clamped to its edge)
  kMissingReference,         // a P or B picture without its reference frame(s): predicted from mid-grey
  kPredictedPictureOnIdec,   // a P or B picture given to the IPU's IDEC path (ipu/ipu_unit.hpp): not decoded
};

const char* issueName(IssueKind k);

struct DecodeIssue {
  IssueKind kind;
  std::size_t byteOffset = 0;  // in the bytes handed to the decoder
  int mbX = -1;                // macroblock column and row, -1 when not tied to a macroblock
  int mbY = -1;
};

struct PictureReport {
  bool produced = false;      // a picture was decoded (possibly with concealment)
  bool undecodable = false;   // a problem that stops decoding altogether (see `issues`)
  int pictureCodingType = 0;  // 1 I, 2 P, 3 B, 4 D
  int temporalReference = 0;
  bool mpeg1 = false;
  int width = 0;
  int height = 0;
  int macroblocks = 0;  // in the picture
  int macroblocksDecoded = 0;
  int macroblocksConcealed = 0;     // kept their previous value (mid-grey for the first picture), or
                                    // predicted from a missing reference frame
  int fieldDctMacroblocks = 0;      // decoded with dct_type = 1
  std::size_t issueCount = 0;       // all issues, also those not kept in `issues`
  std::vector<DecodeIssue> issues;  // the first kMaxIssues

  static constexpr std::size_t kMaxIssues = 32;
  void add(IssueKind kind, std::size_t byteOffset, int mbX = -1, int mbY = -1) {
    ++issueCount;
    if (issues.size() < kMaxIssues) issues.push_back({kind, byteOffset, mbX, mbY});
  }
  bool clean() const { return issueCount == 0; }
  // One line per kept issue: "byte 1234 (mb 3,7): bad VLC code".
  std::string describe() const;
};

}  // namespace vbim::ipu
