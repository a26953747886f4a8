#include "ipu/ipu_commands.hpp"

#include <algorithm>

#include "ipu/bit_reader.hpp"
#include "ipu/slice_syntax.hpp"
#include "ipu/start_code.hpp"
#include "ipu/vlc_tables.hpp"

namespace vbim::ipu {
namespace {

std::uint32_t code(IpuOpcode op) {
  return static_cast<std::uint32_t>(op) << 28;
}

std::uint32_t field(int v, int bits, int shift) {
  return (static_cast<std::uint32_t>(v) & ((1u << bits) - 1u)) << shift;
}

std::uint32_t flag(bool v, int shift) {
  return (v ? 1u : 0u) << shift;
}

int get(std::uint32_t word, int bits, int shift) {
  return static_cast<int>((word >> shift) & ((1u << bits) - 1u));
}

void put(std::string& s, const char* name, int v) {
  if (!s.empty()) s += ' ';
  s += name;
  s += '=';
  s += std::to_string(v);
}

}  // namespace

const char* opcodeName(IpuOpcode op) {
  switch (op) {
    case IpuOpcode::kBclr:
      return "BCLR";
    case IpuOpcode::kIdec:
      return "IDEC";
    case IpuOpcode::kBdec:
      return "BDEC";
    case IpuOpcode::kVdec:
      return "VDEC";
    case IpuOpcode::kFdec:
      return "FDEC";
    case IpuOpcode::kSetiq:
      return "SETIQ";
    case IpuOpcode::kSetvq:
      return "SETVQ";
    case IpuOpcode::kCsc:
      return "CSC";
    case IpuOpcode::kPack:
      return "PACK";
    case IpuOpcode::kSetth:
      return "SETTH";
  }
  return "?";
}

std::uint32_t bclrWord(int bp) {
  return code(IpuOpcode::kBclr) | field(bp, 7, 0);
}

std::uint32_t idecWord(int fb, int qsc, bool dtd, bool sgn, bool dte, bool ofm) {
  return code(IpuOpcode::kIdec) | field(fb, 6, 0) | field(qsc, 5, 16) | flag(dtd, 24) | flag(sgn, 25) | flag(dte, 26) |
         flag(ofm, 27);
}

std::uint32_t bdecWord(int fb, int qsc, bool dt, bool dcr, bool mbi) {
  return code(IpuOpcode::kBdec) | field(fb, 6, 0) | field(qsc, 5, 16) | flag(dt, 25) | flag(dcr, 26) | flag(mbi, 27);
}

std::uint32_t vdecWord(int fb, VdecTable tbl) {
  return code(IpuOpcode::kVdec) | field(fb, 6, 0) | field(static_cast<int>(tbl), 2, 26);
}

std::uint32_t fdecWord(int fb) {
  return code(IpuOpcode::kFdec) | field(fb, 6, 0);
}

std::uint32_t setiqWord(int fb, bool nonIntra) {
  return code(IpuOpcode::kSetiq) | field(fb, 6, 0) | flag(nonIntra, 27);
}

std::uint32_t setvqWord() {
  return code(IpuOpcode::kSetvq);
}

std::uint32_t cscWord(int mbc, bool dte, bool ofm) {
  return code(IpuOpcode::kCsc) | field(mbc, 11, 0) | flag(dte, 26) | flag(ofm, 27);
}

std::uint32_t setthWord(int th0, int th1) {
  return code(IpuOpcode::kSetth) | field(th0, 9, 0) | field(th1, 9, 16);
}

std::string commandFields(std::uint32_t w) {
  std::string s;
  switch (opcodeOf(w)) {
    case IpuOpcode::kBclr:
      put(s, "BP", get(w, 7, 0));
      break;
    case IpuOpcode::kIdec:
      put(s, "FB", get(w, 6, 0));
      put(s, "QSC", get(w, 5, 16));
      put(s, "DTD", get(w, 1, 24));
      put(s, "SGN", get(w, 1, 25));
      put(s, "DTE", get(w, 1, 26));
      put(s, "OFM", get(w, 1, 27));
      break;
    case IpuOpcode::kBdec:
      put(s, "FB", get(w, 6, 0));
      put(s, "QSC", get(w, 5, 16));
      put(s, "DT", get(w, 1, 25));
      put(s, "DCR", get(w, 1, 26));
      put(s, "MBI", get(w, 1, 27));
      break;
    case IpuOpcode::kVdec:
      put(s, "FB", get(w, 6, 0));
      put(s, "TBL", get(w, 2, 26));
      break;
    case IpuOpcode::kFdec:
      put(s, "FB", get(w, 6, 0));
      break;
    case IpuOpcode::kSetiq:
      put(s, "FB", get(w, 6, 0));
      put(s, "IQM", get(w, 1, 27));
      break;
    case IpuOpcode::kSetvq:
      break;
    case IpuOpcode::kCsc:
    case IpuOpcode::kPack:
      put(s, "MBC", get(w, 11, 0));
      put(s, "DTE", get(w, 1, 26));
      put(s, "OFM", get(w, 1, 27));
      break;
    case IpuOpcode::kSetth:
      put(s, "TH0", get(w, 9, 0));
      put(s, "TH1", get(w, 9, 16));
      break;
  }
  return s;
}

std::uint32_t ipuCtrl(const SequenceHeader& seq, const PictureHeader& pic) {
  return field(pic.intraDcPrecision, 2, 16) | flag(pic.alternateScan, 20) | flag(pic.intraVlcFormat, 21) |
         flag(pic.qScaleType, 22) | flag(!seq.mpeg2, 23) | field(pic.codingType, 3, 24);
}

std::string ctrlFields(std::uint32_t c) {
  std::string s;
  put(s, "IDP", get(c, 2, 16));
  put(s, "AS", get(c, 1, 20));
  put(s, "IVF", get(c, 1, 21));
  put(s, "QST", get(c, 1, 22));
  put(s, "MP1", get(c, 1, 23));
  put(s, "PCT", get(c, 3, 24));
  return s;
}

std::vector<SliceStart> sliceStarts(std::span<const std::uint8_t> bytes, const SequenceHeader& seq,
                                    const PictureHeader& pic, int mbWidth, int mbHeight) {
  std::vector<SliceStart> out;
  PictureParams pp;
  pp.mpeg1 = !seq.mpeg2;
  pp.mbWidth = mbWidth;
  pp.mbRows = pic.pictureStructure == 3 ? mbHeight : (mbHeight + 1) / 2;
  pp.tallPicture = seq.height > 2800;
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  for (std::size_t pos = findStartCode(d, n, 0); pos + 3 < n;) {
    const int sc = d[pos + 3];
    const std::size_t next = findStartCode(d, n, pos + 4);
    if (sc >= 0x01 && sc <= 0xAF) {
      BitReader br(d + pos + 4, d + std::min(next, n));
      const SliceHeader h = readSliceHeader(br, pp, sc);
      int inc = 0;
      if (h.ok && readAddressIncrement(br, vlcTables(), inc) && inc >= 1) {
        SliceStart s;
        s.address = static_cast<std::uint32_t>(h.row * mbWidth + inc - 1);
        s.offset = pos;
        s.qsc = h.quantiserScaleCode;
        s.fb = 32 + static_cast<int>(br.position());
        out.push_back(s);
      }
    }
    pos = next;
  }
  return out;
}

}  // namespace vbim::ipu
