#include "ipu/bdec_flow.hpp"

#include <algorithm>

#include "ipu/bit_reader.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {
namespace {

// FDEC reads per header, as libmpeg.c reads them in a release build (fields it reads together are
// one read): its _seq_header 8 fields and 2 load flags, _ext_seq 8, _gop_header 1, _pic_header 3
// (+2 with a forward f_code, +2 with a backward one) and extra_bit_picture, _ext_pic_cod 16.
constexpr int kStartCodeFdec = 2;  // _MPEG_NextStartCode's peek, then GetBits(32)
constexpr int kSequenceHeaderFdec = 10;
constexpr int kSequenceExtensionFdec = 8;
constexpr int kGopFdec = 1;
constexpr int kPictureHeaderFdec = 4;
constexpr int kPictureCodingExtensionFdec = 16;
constexpr int kOtherExtensionFdec = 3;
constexpr int kQuantMatrixExtensionFdec = 4;  // the four load flags

// _MPEG_SetDefQM: the EE suspends the IPU (BCLR), writes both default matrices into the FIFO with
// a SETIQ each, and resumes (BCLR with the saved bit pointer).
// BitReader::skip takes at most 32 bits at a time.
void skipBits(BitReader& br, int n) {
  for (; n > 32; n -= 32) br.skip(32);
  br.skip(n);
}

void defaultMatrices(IpuCommandCounts& c, std::vector<std::uint32_t>* words) {
  c.bclr += 2;
  c.setiq += 2;
  if (words != nullptr)
    words->insert(words->end(), {bclrWord(0), setiqWord(0, false), setiqWord(0, true), bclrWord(0)});
}

// Appends `n` FDEC words (FB = 0) and counts them.
void fdecs(IpuCommandCounts& c, int n, std::vector<std::uint32_t>* words) {
  c.fdec += n;
  if (words != nullptr) words->insert(words->end(), static_cast<std::size_t>(n), fdecWord(0));
}

void setiq(IpuCommandCounts& c, bool nonIntra, std::vector<std::uint32_t>* words) {
  ++c.setiq;
  if (words != nullptr) words->push_back(setiqWord(0, nonIntra));
}

}  // namespace

IpuCommandCounts& IpuCommandCounts::operator+=(const IpuCommandCounts& o) {
  bclr += o.bclr;
  idec += o.idec;
  bdec += o.bdec;
  vdec += o.vdec;
  fdec += o.fdec;
  setiq += o.setiq;
  setvq += o.setvq;
  csc += o.csc;
  return *this;
}

IpuCommandCounts headerCommands(std::span<const std::uint8_t> bytes, std::uint32_t& headerBytes,
                                std::vector<std::uint32_t>* words) {
  IpuCommandCounts c;
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  std::size_t pos = findStartCode(d, n, 0);
  headerBytes = static_cast<std::uint32_t>(n);
  while (pos + 3 < n) {
    const int code = d[pos + 3];
    const std::size_t next = findStartCode(d, n, pos + 4);
    if (code >= 0x01 && code <= 0xAF) {
      headerBytes = static_cast<std::uint32_t>(pos);
      break;
    }
    BitReader br(d + pos + 4, d + next);
    fdecs(c, kStartCodeFdec, words);
    if (code == 0xB3) {  // sequence header: a matrix loaded with SETIQ from the stream, or defaults
      fdecs(c, kSequenceHeaderFdec, words);
      skipBits(br, 62);
      const bool intra = br.readBit();
      if (intra) skipBits(br, 64 * 8);
      const bool nonIntra = br.readBit();
      for (const bool nonIntraMatrix : {false, true}) {
        if (nonIntraMatrix ? nonIntra : intra) {
          setiq(c, nonIntraMatrix, words);
        } else {
          defaultMatrices(c, words);
        }
      }
    } else if (code == 0xB8) {
      fdecs(c, kGopFdec, words);
    } else if (code == 0x00) {
      const int type = static_cast<int>((br.peek(13)) & 7);
      fdecs(c, kPictureHeaderFdec + (type == 2 || type == 3 ? 2 : 0) + (type == 3 ? 2 : 0), words);
    } else if (code == 0xB5) {
      const int id = static_cast<int>(br.read(4));
      fdecs(c, 1, words);
      if (id == 1) {
        fdecs(c, kSequenceExtensionFdec, words);
      } else if (id == 8) {
        fdecs(c, kPictureCodingExtensionFdec, words);
      } else if (id == 3) {  // quant matrix extension: the intra and non-intra matrices are the IPU's
        fdecs(c, kQuantMatrixExtensionFdec, words);
        const bool intra = br.readBit();
        if (intra) skipBits(br, 64 * 8);
        const bool nonIntra = br.readBit();
        if (intra) setiq(c, false, words);
        if (nonIntra) setiq(c, true, words);
      } else {
        fdecs(c, kOtherExtensionFdec, words);
      }
    }
    pos = next;
  }
  return c;
}

FlowPicture buildFlow(std::span<const std::uint8_t> bytes, const std::vector<MacroblockBits>& trace, bool intraPicture,
                      bool fieldDct) {
  FlowPicture f;
  f.inQwords = static_cast<std::uint32_t>((bytes.size() + 15) / 16);
  std::uint32_t headerBytes = 0;
  f.header = headerCommands(bytes, headerBytes, &f.headerWords);
  f.headerQwords = std::min(f.inQwords, (headerBytes + 15) / 16);
  std::uint32_t need = f.headerQwords;
  for (const MacroblockBits& m : trace) {
    FlowMacroblock skip;
    skip.skipped = true;
    skip.address = m.address >= m.skippedBefore ? m.address - m.skippedBefore : 0;
    skip.needQwords = need;
    skip.predictions = m.skippedPredictions;
    skip.averaged = m.skippedPredictions > 1 ? 1 : 0;
    for (int k = 0; k < m.skippedBefore; ++k) {
      f.macroblocks.push_back(skip);
      ++skip.address;
    }
    FlowMacroblock mb;
    mb.address = m.address;
    mb.sliceStart = m.sliceStart;
    if (intraPicture) {
      mb.vdec = 2;  // address increment, macroblock_type
      mb.fdec = fieldDct ? 1 : 0;
      mb.bdec = true;
      mb.intra = true;
      mb.blockBits = m.bits;
    } else {
      mb.vdec = m.vdec;
      mb.fdec = m.fdec;
      mb.bdec = m.bdec;
      mb.intra = m.bdec && m.predictions == 0;
      mb.blockBits = m.blockBits;
      mb.predictions = m.predictions;
      mb.averaged = m.averaged;
    }
    if (mb.sliceStart) mb.fdec = static_cast<std::uint16_t>(mb.fdec + kSliceHeaderFdec);
    need = std::max(need, std::min(f.inQwords, (m.endByte + 15) / 16));
    mb.needQwords = need;
    f.macroblocks.push_back(mb);
  }
  return f;
}

}  // namespace vbim::ipu
