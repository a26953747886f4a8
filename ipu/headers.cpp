#include "ipu/headers.hpp"

#include "ipu/quant_tables.hpp"

namespace vbim::ipu {
namespace {

// Matrices are sent in zigzag order whatever the scan in force (§6.3.11).
void readMatrix(BitReader& br, std::array<std::uint8_t, 64>& m) {
  for (int i = 0; i < 64; ++i) m[kZigzagScan[i]] = static_cast<std::uint8_t>(br.read(8));
}

}  // namespace

bool parseSequenceHeader(BitReader& br, SequenceHeader& seq) {
  SequenceHeader s;
  s.width = static_cast<int>(br.read(12));
  s.height = static_cast<int>(br.read(12));
  s.aspectRatio = static_cast<int>(br.read(4));
  s.frameRateCode = static_cast<int>(br.read(4));
  br.skip(18);  // bit_rate_value
  br.skip(1);   // marker_bit
  br.skip(10);  // vbv_buffer_size_value
  br.skip(1);   // constrained_parameters_flag
  s.intraMatrix = kDefaultIntraMatrix;
  if (br.readBit()) readMatrix(br, s.intraMatrix);
  s.nonIntraMatrix.fill(16);
  if (br.readBit()) readMatrix(br, s.nonIntraMatrix);
  if (br.overrun()) return false;
  // A zero entry would make every coefficient vanish; the standard forbids it (§6.3.11).
  for (std::uint8_t w : s.intraMatrix)
    if (w == 0) return false;
  seq = s;
  return true;
}

bool parseSequenceExtension(BitReader& br, SequenceHeader& seq) {
  // extension_start_code_identifier (4 bits, = 1) already read by the caller.
  const int profileAndLevel = static_cast<int>(br.read(8));
  const bool progressive = br.readBit();
  const int chroma = static_cast<int>(br.read(2));
  const int hExt = static_cast<int>(br.read(2));
  const int vExt = static_cast<int>(br.read(2));
  br.skip(12);  // bit_rate_extension
  br.skip(1);   // marker_bit
  br.skip(8);   // vbv_buffer_size_extension
  br.skip(1);   // low_delay
  br.skip(2);   // frame_rate_extension_n
  br.skip(5);   // frame_rate_extension_d
  if (br.overrun() || chroma == 0) return false;
  seq.mpeg2 = true;
  seq.profileAndLevel = profileAndLevel;
  seq.progressiveSequence = progressive;
  seq.chromaFormat = chroma;
  seq.width = (seq.width & 0xFFF) | (hExt << 12);
  seq.height = (seq.height & 0xFFF) | (vExt << 12);
  return true;
}

bool parseQuantMatrixExtension(BitReader& br, SequenceHeader& seq) {
  std::array<std::uint8_t, 64> intra = seq.intraMatrix, nonIntra = seq.nonIntraMatrix, unused{};
  if (br.readBit()) readMatrix(br, intra);
  if (br.readBit()) readMatrix(br, nonIntra);
  // Chroma matrices apply to 4:2:2 / 4:4:4 only; read past them.
  if (br.readBit()) readMatrix(br, unused);
  if (br.readBit()) readMatrix(br, unused);
  if (br.overrun()) return false;
  for (std::uint8_t w : intra)
    if (w == 0) return false;
  seq.intraMatrix = intra;
  seq.nonIntraMatrix = nonIntra;
  return true;
}

bool parsePictureHeader(BitReader& br, PictureHeader& pic) {
  PictureHeader p;
  p.temporalReference = static_cast<int>(br.read(10));
  p.codingType = static_cast<int>(br.read(3));
  br.skip(16);  // vbv_delay
  for (int s = 0; s < 2 && p.codingType >= 2 + s && p.codingType <= 3; ++s) {
    p.fullPel[s] = br.readBit();
    p.headerFCode[s] = static_cast<int>(br.read(3));
  }
  // extra_information_picture: bounded by the header's bytes (the reader returns zeros past them).
  while (br.readBit()) {
    br.skip(8);
    if (br.overrun()) return false;
  }
  if (br.overrun() || p.codingType < 1 || p.codingType > 4) return false;
  pic = p;
  return true;
}

bool parsePictureCodingExtension(BitReader& br, PictureHeader& pic) {
  PictureHeader p = pic;
  p.fCode[0][0] = static_cast<int>(br.read(4));
  p.fCode[0][1] = static_cast<int>(br.read(4));
  p.fCode[1][0] = static_cast<int>(br.read(4));
  p.fCode[1][1] = static_cast<int>(br.read(4));
  p.intraDcPrecision = static_cast<int>(br.read(2));
  p.pictureStructure = static_cast<int>(br.read(2));
  p.topFieldFirst = br.readBit();
  p.framePredFrameDct = br.readBit();
  p.concealmentMotionVectors = br.readBit();
  p.qScaleType = br.readBit();
  p.intraVlcFormat = br.readBit();
  p.alternateScan = br.readBit();
  br.skip(1);  // repeat_first_field
  br.skip(1);  // chroma_420_type
  p.progressiveFrame = br.readBit();
  // composite_display_flag and its fields are not needed.
  if (br.overrun() || p.pictureStructure == 0) return false;
  p.hasCodingExtension = true;
  pic = p;
  return true;
}

}  // namespace vbim::ipu
