#include "ipu/bdec_flow.hpp"

#include <algorithm>

#include "ipu/bit_reader.hpp"
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

void defaultMatrices(IpuCommandCounts& c) {
  c.bclr += 2;
  c.setiq += 2;
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

IpuCommandCounts headerCommands(std::span<const std::uint8_t> bytes, std::uint32_t& headerBytes) {
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
    c.fdec += kStartCodeFdec;
    if (code == 0xB3) {  // sequence header: a matrix loaded with SETIQ from the stream, or defaults
      c.fdec += kSequenceHeaderFdec;
      skipBits(br, 62);
      const bool intra = br.readBit();
      if (intra) skipBits(br, 64 * 8);
      const bool nonIntra = br.readBit();
      for (const bool loaded : {intra, nonIntra}) {
        if (loaded) {
          ++c.setiq;
        } else {
          defaultMatrices(c);
        }
      }
    } else if (code == 0xB8) {
      c.fdec += kGopFdec;
    } else if (code == 0x00) {
      const int type = static_cast<int>((br.peek(13)) & 7);
      c.fdec += kPictureHeaderFdec + (type == 2 || type == 3 ? 2 : 0) + (type == 3 ? 2 : 0);
    } else if (code == 0xB5) {
      const int id = static_cast<int>(br.read(4));
      c.fdec += 1;
      if (id == 1) {
        c.fdec += kSequenceExtensionFdec;
      } else if (id == 8) {
        c.fdec += kPictureCodingExtensionFdec;
      } else if (id == 3) {  // quant matrix extension: the intra and non-intra matrices are the IPU's
        c.fdec += kQuantMatrixExtensionFdec;
        const bool intra = br.readBit();
        if (intra) skipBits(br, 64 * 8);
        const bool nonIntra = br.readBit();
        c.setiq += (intra ? 1 : 0) + (nonIntra ? 1 : 0);
      } else {
        c.fdec += kOtherExtensionFdec;
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
  f.header = headerCommands(bytes, headerBytes);
  f.headerQwords = std::min(f.inQwords, (headerBytes + 15) / 16);
  std::uint32_t need = f.headerQwords;
  for (const MacroblockBits& m : trace) {
    FlowMacroblock skip;
    skip.skipped = true;
    skip.needQwords = need;
    skip.predictions = m.skippedPredictions;
    skip.averaged = m.skippedPredictions > 1 ? 1 : 0;
    for (int k = 0; k < m.skippedBefore; ++k) f.macroblocks.push_back(skip);
    FlowMacroblock mb;
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
