// Sequence, GOP and picture layer headers and their extensions (ISO/IEC 13818-2 §6.2.2-6.2.3,
// §6.3; the MPEG-1 forms of 11172-2 §2.4.2). Each parser reads one header's bytes (after its start
// code, up to the next start code) and returns false if they are too short or invalid.
#pragma once

#include <array>
#include <cstdint>

#include "ipu/bit_reader.hpp"

namespace vbim::ipu {

inline constexpr std::uint8_t kPictureStartCode = 0x00;
inline constexpr std::uint8_t kSliceFirst = 0x01;
inline constexpr std::uint8_t kSliceLast = 0xAF;
inline constexpr std::uint8_t kUserDataStartCode = 0xB2;
inline constexpr std::uint8_t kSequenceHeaderCode = 0xB3;
inline constexpr std::uint8_t kSequenceErrorCode = 0xB4;
inline constexpr std::uint8_t kExtensionStartCode = 0xB5;
inline constexpr std::uint8_t kSequenceEndCode = 0xB7;
inline constexpr std::uint8_t kGroupStartCode = 0xB8;

struct SequenceHeader {
  int width = 0;  // horizontal_size (with the sequence extension's high bits)
  int height = 0;
  int aspectRatio = 0;
  int frameRateCode = 0;
  bool mpeg2 = false;  // a sequence extension followed the header
  int profileAndLevel = 0;
  bool progressiveSequence = true;
  int chromaFormat = 1;                           // 1 = 4:2:0, 2 = 4:2:2, 3 = 4:4:4
  std::array<std::uint8_t, 64> intraMatrix{};     // raster order
  std::array<std::uint8_t, 64> nonIntraMatrix{};  // raster order (kept, unused by intra decode)
};

struct PictureHeader {
  int temporalReference = 0;
  int codingType = 0;  // 1 I, 2 P, 3 B, 4 D
  // The picture header's vector fields (MPEG-1 uses them; MPEG-2 sets them to 0 and 7 and uses f_code):
  // full_pel_forward_vector, forward_f_code, full_pel_backward_vector, backward_f_code.
  bool fullPel[2] = {false, false};
  int headerFCode[2] = {7, 7};
  bool hasCodingExtension = false;
  int fCode[2][2] = {{15, 15}, {15, 15}};
  int intraDcPrecision = 0;  // 0..3 = 8..11 bits
  int pictureStructure = 3;  // 1 top field, 2 bottom field, 3 frame
  bool topFieldFirst = false;
  bool framePredFrameDct = true;
  bool concealmentMotionVectors = false;
  bool qScaleType = false;      // non-linear quantiser scale
  bool intraVlcFormat = false;  // B.15 for intra AC
  bool alternateScan = false;
  bool progressiveFrame = true;
};

// The sequence header resets both matrices to their defaults unless it loads them.
bool parseSequenceHeader(BitReader& br, SequenceHeader& seq);
bool parseSequenceExtension(BitReader& br, SequenceHeader& seq);
bool parseQuantMatrixExtension(BitReader& br, SequenceHeader& seq);
bool parsePictureHeader(BitReader& br, PictureHeader& pic);
bool parsePictureCodingExtension(BitReader& br, PictureHeader& pic);

}  // namespace vbim::ipu
