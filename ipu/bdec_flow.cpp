#include "ipu/bdec_flow.hpp"

#include <algorithm>
#include <initializer_list>
#include <span>

#include "ipu/bit_reader.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {
namespace {

// The FDEC reads of each header as libmpeg.c reads them in a release build (fields it reads
// together are one read), each an FDEC with FB = its width (_MPEG_GetBits(n) of libmpeg_core.c
// issues FDEC | n): _MPEG_NextStartCode's peek then GetBits(32); _seq_header's 8 fields (its two
// load flags follow, each before its matrix); _gop_header's 27 bits in one; _pic_header's
// temporal_reference, picture_coding_type, vbv_delay (+ full_pel and f_code forward, + backward)
// and extra_bit_picture; the extension's id; _ext_seq 8; _ext_pic_cod 15 (_MPEG_SetIDCP and
// _MPEG_SetQSTIVFAS are 1 and 3 of them; chroma_420_type and progressive_frame one GetBits(2)).
constexpr int kStartCodeWidths[] = {0, 32};
constexpr int kSequenceHeaderWidths[] = {12, 12, 4, 4, 18, 1, 10, 1};
constexpr int kGopWidths[] = {27};
constexpr int kPictureHeaderWidths[] = {10, 3, 16};
constexpr int kVectorCodeWidths[] = {1, 3};  // full_pel_*_vector, *_f_code
constexpr int kSequenceExtensionWidths[] = {8, 1, 2, 2, 2, 22, 2, 5};
constexpr int kPictureCodingExtensionWidths[] = {4, 4, 4, 4, 2, 2, 1, 1, 1, 1, 1, 1, 1, 2, 1};
// Other extensions: 3 reads; their widths for the sequence display (without colour description)
// and copyright extensions, FB = 0 for the rest.
constexpr int kSequenceDisplayWidths[] = {3, 1, 29};
constexpr int kCopyrightWidths[] = {32, 32, 20};

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

// Appends an FDEC word per width (FB = the width) and counts them.
void fdecs(IpuCommandCounts& c, std::span<const int> widths, std::vector<std::uint32_t>* words) {
  c.fdec += static_cast<std::int64_t>(widths.size());
  if (words == nullptr) return;
  for (const int w : widths) words->push_back(fdecWord(w));
}

void fdecs(IpuCommandCounts& c, std::initializer_list<int> widths, std::vector<std::uint32_t>* words) {
  fdecs(c, std::span<const int>(widths.begin(), widths.size()), words);
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
    fdecs(c, kStartCodeWidths, words);
    if (code == 0xB3) {  // sequence header: each matrix after its load flag, from the stream or defaults
      fdecs(c, kSequenceHeaderWidths, words);
      skipBits(br, 62);
      const bool intra = br.readBit();
      if (intra) skipBits(br, 64 * 8);
      const bool nonIntra = br.readBit();
      for (const bool nonIntraMatrix : {false, true}) {
        fdecs(c, {1}, words);
        if (nonIntraMatrix ? nonIntra : intra) {
          setiq(c, nonIntraMatrix, words);
        } else {
          defaultMatrices(c, words);
        }
      }
    } else if (code == 0xB8) {
      fdecs(c, kGopWidths, words);
    } else if (code == 0x00) {
      const int type = static_cast<int>((br.peek(13)) & 7);
      fdecs(c, kPictureHeaderWidths, words);
      if (type == 2 || type == 3) fdecs(c, kVectorCodeWidths, words);
      if (type == 3) fdecs(c, kVectorCodeWidths, words);
      fdecs(c, {1}, words);  // extra_bit_picture
    } else if (code == 0xB5) {
      const int id = static_cast<int>(br.read(4));
      fdecs(c, {4}, words);
      if (id == 1) {
        fdecs(c, kSequenceExtensionWidths, words);
      } else if (id == 8) {
        fdecs(c, kPictureCodingExtensionWidths, words);
      } else if (id == 3) {  // quant matrix extension: the intra and non-intra matrices are the IPU's
        const bool intra = br.readBit();
        if (intra) skipBits(br, 64 * 8);
        const bool nonIntra = br.readBit();
        fdecs(c, {1}, words);
        if (intra) setiq(c, false, words);
        fdecs(c, {1}, words);
        if (nonIntra) setiq(c, true, words);
        fdecs(c, {1, 1}, words);  // the chroma matrices' flags (4:2:2 and 4:4:4 only)
      } else if (id == 2) {
        fdecs(c, kSequenceDisplayWidths, words);
      } else if (id == 4) {
        fdecs(c, kCopyrightWidths, words);
      } else {
        fdecs(c, {0, 0, 0}, words);  // three reads of widths not modelled
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
