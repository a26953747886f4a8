// The IPU command log (issue #30): command words laid out as PCSX2's IPU.h and T-IPU define them,
// the commands an intra picture (BCLR, IDEC per slice) and a GOP stream's pictures (the BDEC flow)
// issue, in order, and their times against the coalesced trace spans.
#include "ipu/ipu_commands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

#include "ipu/elementary_stream.hpp"
#include "ipu/ipu_unit.hpp"
#include "runtime/trace_stream.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes intraPicture(bool interlacedDct = false) {
  testing::EncodeOptions o;
  o.width = 128;
  o.height = 64;
  o.frames = 1;
  o.quantiser = 3;
  o.content = testing::Content::kBusy;
  o.interlacedDct = interlacedDct;
  return testing::encodePictures(o).at(0);
}

// The slice start codes of a picture (00 00 01 then 01..AF), read here byte by byte.
std::vector<std::size_t> sliceCodes(const Bytes& b) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + 4 < b.size(); ++i) {
    if (b[i] == 0 && b[i + 1] == 0 && b[i + 2] == 1 && b[i + 3] >= 0x01 && b[i + 3] <= 0xAF) at.push_back(i);
  }
  return at;
}

std::map<IpuOpcode, std::int64_t> countOps(const std::vector<IssuedCommand>& cs) {
  std::map<IpuOpcode, std::int64_t> n;
  for (const IssuedCommand& c : cs) ++n[opcodeOf(c.word)];
  return n;
}

TEST(IpuCommandWords, FieldsSitWherePcsx2AndPs2tekPutThem) {
  // IDEC: code 1, FB 0-5, QSC 16-20, DTD 24, SGN 25, DTE 26, OFM 27 (P-IPU tIPU_CMD_IDEC).
  EXPECT_EQ(idecWord(39, 6, false, false, false, false), 0x10060027u);
  EXPECT_EQ(idecWord(0, 0, true, false, false, false), 0x11000000u);
  EXPECT_EQ(idecWord(0, 0, false, true, false, false), 0x12000000u);
  EXPECT_EQ(idecWord(0, 0, false, false, true, false), 0x14000000u);
  EXPECT_EQ(idecWord(0, 0, false, false, false, true), 0x18000000u);
  EXPECT_EQ(idecWord(63, 31, false, false, false, false), 0x101F003Fu);
  // BDEC: code 2, QSC 16-20, DT 25, DCR 26, MBI 27 (P-IPU tIPU_CMD_BDEC).
  EXPECT_EQ(bdecWord(0, 31, false, false, false), 0x201F0000u);
  EXPECT_EQ(bdecWord(0, 0, true, false, false), 0x22000000u);
  EXPECT_EQ(bdecWord(0, 0, false, true, false), 0x24000000u);
  EXPECT_EQ(bdecWord(0, 0, false, false, true), 0x28000000u);
  // VDEC TBL 26-27 (P-IPU ipuVDEC: (val >> 26) & 3), FDEC FB, SETIQ IQM 27, CSC MBC 0-10 DTE 26 OFM 27,
  // SETTH TH0 0-8 TH1 16-24 (ipuSETTH), BCLR BP 0-6 (ipuBCLR).
  EXPECT_EQ(vdecWord(0, VdecTable::kAddressIncrement), 0x30000000u);
  EXPECT_EQ(vdecWord(0, VdecTable::kMacroblockType), 0x34000000u);
  EXPECT_EQ(vdecWord(0, VdecTable::kDmVector), 0x3C000000u);
  EXPECT_EQ(fdecWord(32), 0x40000020u);
  EXPECT_EQ(setiqWord(0, true), 0x58000000u);
  EXPECT_EQ(setvqWord(), 0x60000000u);
  EXPECT_EQ(cscWord(0x3FF, true, true), 0x7C0003FFu);
  EXPECT_EQ(setthWord(32, 96), 0x90600020u);
  EXPECT_EQ(bclrWord(88), 0x00000058u);
  EXPECT_EQ(commandFields(0x10060027u), "FB=39 QSC=6 DTD=0 SGN=0 DTE=0 OFM=0");
  EXPECT_EQ(commandFields(0x2C1F0000u), "FB=0 QSC=31 DT=0 DCR=1 MBI=1");
  EXPECT_EQ(commandFields(0x7C0003FFu), "MBC=1023 DTE=1 OFM=1");
  EXPECT_EQ(commandFields(0x90600020u), "TH0=32 TH1=96");
  EXPECT_STREQ(opcodeName(opcodeOf(0x7C0003FFu)), "CSC");
  // IPU_CTRL: IDP 16-17, AS 20, IVF 21, QST 22, MP1 23, PCT 24-26 (P-IPU tIPU_CTRL).
  SequenceHeader seq;
  seq.mpeg2 = true;
  PictureHeader pic;
  pic.codingType = 2;
  pic.intraDcPrecision = 2;
  pic.alternateScan = true;
  pic.intraVlcFormat = true;
  pic.qScaleType = true;
  EXPECT_EQ(ipuCtrl(seq, pic), 0x02720000u);
  seq.mpeg2 = false;
  pic = PictureHeader{};
  pic.codingType = 1;
  EXPECT_EQ(ipuCtrl(seq, pic), 0x01800000u);  // MPEG-1 I picture
  EXPECT_EQ(ctrlFields(0x01800000u), "IDP=0 AS=0 IVF=0 QST=0 MP1=1 PCT=1");
}

struct Logged {
  TimedPicture tp;
  std::string json;
};

Task<void> decodeAll(IpuUnit& unit, StreamId id, const std::vector<Bytes>* pics, std::vector<TimedPicture>* out,
                     bool flush) {
  for (const Bytes& b : *pics) {
    Rgba8Image img;
    out->push_back(co_await unit.decode(id, b, img));
  }
  if (flush) {
    Rgba8Image img;
    out->push_back(co_await unit.flush(id, img));
  }
}

// Decodes `pics` on a new stream of `path` with the command log on, the trace streamed coalesced.
std::vector<TimedPicture> logged(const std::vector<Bytes>& pics, DecodePath path, std::string* json = nullptr,
                                 bool rgb16 = false) {
  Scheduler s;
  Tracer tracer;
  std::ostringstream js;
  std::ostringstream vcd;
  IpuUnit unit(s, IpuParams{}, &tracer);
  if (rgb16) unit.setRgb16Output(true);
  unit.recordCommands();
  const StreamId id = path == DecodePath::kIdec ? kSharedIdecStream : unit.openStream(path);
  tracer.streamTo(js, vcd, TraceDetail::Coalesced);
  std::vector<TimedPicture> out;
  s.spawn("player", decodeAll(unit, id, &pics, &out, path == DecodePath::kBdec));
  s.run();
  tracer.finish();
  if (json != nullptr) *json = js.str();
  return out;
}

std::string span(const char* name, Tick begin, Tick end) {
  const long long b = trace_format::nanos(begin);
  return std::string(R"({"name":")") + name + R"(","ph":"X","pid":1,"tid":1,"ts":)" + trace_format::micros(b) +
         R"(,"dur":)" + trace_format::micros(trace_format::nanos(end) - b) + "}";
}

TEST(IpuCommandLog, IntraPictureIsBclrThenOneIdecPerSliceWithItsHeaderSkipAndScale) {
  const Bytes pic = intraPicture();
  std::string json;
  const std::vector<TimedPicture> r = logged({pic}, DecodePath::kIdec, &json);
  ASSERT_EQ(r.size(), 1u);
  const TimedPicture& tp = r[0];
  ASSERT_TRUE(tp.report.produced);
  const std::vector<std::size_t> slices = sliceCodes(pic);
  ASSERT_EQ(slices.size(), 4u);  // 128x64: one slice per macroblock row
  ASSERT_EQ(tp.issued.size(), 1 + slices.size());
  ASSERT_EQ(tp.idecCommands, static_cast<std::int64_t>(slices.size()));
  // BCLR: the first slice start code's bit position in its qword (toIPU DMA moves whole qwords).
  EXPECT_EQ(tp.issued[0].word, bclrWord(static_cast<int>(8 * (slices[0] & 15))));
  EXPECT_EQ(tp.issued[0].begin, tp.started);
  EXPECT_EQ(tp.ctrl, 0x01000000u);  // MPEG-2, 8-bit DC, zigzag, B.14, linear q, I picture
  const IpuParams p;
  for (std::size_t k = 0; k < slices.size(); ++k) {
    SCOPED_TRACE("slice " + std::to_string(k));
    const IssuedCommand& c = tp.issued[1 + k];
    // quantiser_scale_code: the 5 bits after the start code; then extra_bit_slice 0 and the first
    // macroblock_address_increment '1': FB = 32 + 5 + 1 + 1.
    const int qsc = pic[slices[k] + 4] >> 3;
    EXPECT_EQ(c.word, idecWord(39, qsc, false, false, false, false)) << commandFields(c.word);
    EXPECT_LT(c.begin, c.end);
    // The coalesced trace shows each IDEC's macroblocks as one `decode` span, from its start delay
    // to its last macroblock's last row; between two, the EE's restart.
    EXPECT_NE(json.find(span("decode", c.begin + p.idec_start_cycles, c.end)), std::string::npos);
    if (k > 0) {
      EXPECT_EQ(c.begin, tp.issued[k].end + p.slice_restart_cycles);
      EXPECT_NE(json.find(span("idec restart", tp.issued[k].end, c.begin + p.idec_start_cycles)), std::string::npos);
    }
  }
  // The last qword leaves by fromIPU after the last IDEC's last row.
  EXPECT_EQ(tp.finished, tp.issued.back().end + kQwordsPerRow * p.fromipu_cycles_per_qword);
}

TEST(IpuCommandLog, Rgb16OutputSetsOfmAndDteAndHalvesTheFromIpuQwords) {
  const Bytes pic = intraPicture();
  const TimedPicture rgb32 = logged({pic}, DecodePath::kIdec).at(0);
  const TimedPicture rgb16 = logged({pic}, DecodePath::kIdec, nullptr, true).at(0);
  EXPECT_EQ(rgb32.outputQwords, 32 * 64);
  EXPECT_EQ(rgb16.outputQwords, 32 * 32);
  ASSERT_EQ(rgb16.issued.size(), rgb32.issued.size());
  for (std::size_t k = 1; k < rgb16.issued.size(); ++k) {
    EXPECT_EQ(rgb16.issued[k].word, rgb32.issued[k].word | 0x0C000000u);  // OFM = 1, DTE = 1
    EXPECT_EQ(rgb16.issued[k].end, rgb32.issued[k].end);                  // CSC-bound: the core's time is the same
  }
  // The drain keeps up with CSC either way: the picture is in memory 2 DMA periods after its last
  // row instead of 4.
  EXPECT_EQ(rgb16.finished, rgb32.finished - 2);
}

TEST(IpuCommandLog, FieldDctPictureSetsDtd) {
  const Bytes pic = intraPicture(true);
  const TimedPicture tp = logged({pic}, DecodePath::kIdec).at(0);
  ASSERT_GT(tp.issued.size(), 1u);
  for (std::size_t k = 1; k < tp.issued.size(); ++k) EXPECT_EQ((tp.issued[k].word >> 24) & 1, 1u);  // DTD
}

TEST(IpuCommandLog, GopStreamFollowsTheBdecFlow) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = 7;
  o.gopSize = 6;
  o.bFrames = 2;
  o.quantiser = 4;
  o.content = testing::Content::kPattern;
  const std::vector<Bytes> pics = testing::encodePictures(o);
  const std::vector<TimedPicture> r = logged(pics, DecodePath::kBdec);
  ASSERT_EQ(r.size(), pics.size() + 1);
  bool sawP = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    SCOPED_TRACE("picture " + std::to_string(i));
    const TimedPicture& tp = r[i];
    const std::vector<IssuedCommand>& cs = tp.issued;
    ASSERT_FALSE(cs.empty());
    // Every command the flow counts is in the log, and nothing else.
    std::map<IpuOpcode, std::int64_t> n = countOps(cs);
    EXPECT_EQ(n[IpuOpcode::kBclr], tp.commands.bclr);
    EXPECT_EQ(n[IpuOpcode::kIdec], 0);
    EXPECT_EQ(n[IpuOpcode::kBdec], tp.commands.bdec);
    EXPECT_EQ(n[IpuOpcode::kVdec], tp.commands.vdec);
    EXPECT_EQ(n[IpuOpcode::kFdec], tp.commands.fdec);
    EXPECT_EQ(n[IpuOpcode::kSetiq], tp.commands.setiq);
    EXPECT_EQ(n[IpuOpcode::kCsc], tp.commands.csc);
    // BCLR at the picture's start, when the EE starts it.
    EXPECT_EQ(opcodeOf(cs[0].word), IpuOpcode::kBclr);
    EXPECT_GE(cs[0].begin, tp.started);
    // In issue order, one at a time: each starts when the one before has ended.
    for (std::size_t k = 1; k < cs.size(); ++k) {
      ASSERT_LE(cs[k].begin, cs[k].end) << k;
      ASSERT_GE(cs[k].begin, cs[k - 1].end) << k << " " << commandFields(cs[k].word);
    }
    EXPECT_LE(cs.back().end, tp.finished);
    if (i == r.size() - 1) {  // the flush: only the last frame's CSC
      ASSERT_EQ(n[IpuOpcode::kBdec], 0);
    } else {
      ASSERT_GT(n[IpuOpcode::kBdec], 0);
      const int type = tp.report.pictureCodingType;
      EXPECT_EQ((tp.ctrl >> 24) & 7, static_cast<std::uint32_t>(type));
      // Before each BDEC: VDEC of its address increment and type (TBL 0, 1) after the slice's FDECs.
      std::int64_t bdecs = 0;
      std::int64_t intra = 0;
      for (std::size_t k = 0; k < cs.size(); ++k) {
        if (opcodeOf(cs[k].word) != IpuOpcode::kBdec) continue;
        ++bdecs;
        const bool mbi = ((cs[k].word >> 27) & 1) != 0;
        intra += mbi ? 1 : 0;
        std::size_t j = k;
        while (j > 0 && cs[j - 1].word != vdecWord(0, VdecTable::kAddressIncrement)) {
          ASSERT_NE(opcodeOf(cs[j - 1].word), IpuOpcode::kBdec) << "two BDECs without a VDEC between";
          --j;
        }
        ASSERT_GT(j, 0u);
        EXPECT_EQ(cs[j].word, vdecWord(0, VdecTable::kMacroblockType));
      }
      if (type == 1) {
        EXPECT_EQ(intra, bdecs);  // every macroblock of an I picture is intra (MBI = 1)
        // DCR = 1 at each slice start only (all intra): as many as slices.
        std::int64_t dcr = 0;
        for (const IssuedCommand& c : cs) dcr += opcodeOf(c.word) == IpuOpcode::kBdec && ((c.word >> 26) & 1) ? 1 : 0;
        EXPECT_EQ(dcr, static_cast<std::int64_t>(sliceCodes(pics[i]).size()));
      } else {
        sawP = sawP || type == 2;
        EXPECT_LT(intra, bdecs);
      }
    }
    if (tp.displayed) {
      // _MPEG_CSCImage: BCLR, CSC of the frame's 24 macroblocks (RGB32), BCLR.
      ASSERT_GE(cs.size(), 3u);
      EXPECT_EQ(opcodeOf(cs[cs.size() - 3].word), IpuOpcode::kBclr);
      EXPECT_EQ(cs[cs.size() - 2].word, cscWord(24, false, false));
      EXPECT_EQ(opcodeOf(cs.back().word), IpuOpcode::kBclr);
    } else {
      EXPECT_EQ(n[IpuOpcode::kCsc], 0);
    }
  }
  EXPECT_TRUE(sawP);
}

// The BDEC flow's words carry their fields as libmpeg writes them (ee/mpeg/src/libmpeg.c,
// libmpeg_core.c): the headers' FDECs with FB = each read's width, a macroblock's FDECs with its
// fields' widths, BDEC with FB = 0, the quantiser_scale_code in force and DT = its dct_type.
TEST(IpuCommandLog, BdecFlowWordsCarryWidthsAndDctType) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = 4;
  o.gopSize = 4;
  o.bFrames = 1;
  o.quantiser = 3;
  o.interlacedDct = true;
  o.interlacedMe = true;
  o.content = testing::Content::kInterlaced;
  const std::vector<Bytes> pics = testing::encodePictures(o);
  const std::vector<TimedPicture> r = logged(pics, DecodePath::kBdec);
  ASSERT_EQ(r.size(), pics.size() + 1);
  // The first picture's words open with BCLR, the sequence header's start code (its peek and 32
  // bits) and its eight fields (_seq_header), then the intra matrix's load flag.
  const std::vector<IssuedCommand>& first = r[0].issued;
  const std::vector<std::uint32_t> opening{bclrWord(0),  fdecWord(0),  fdecWord(32), fdecWord(12),
                                           fdecWord(12), fdecWord(4),  fdecWord(4),  fdecWord(18),
                                           fdecWord(1),  fdecWord(10), fdecWord(1),  fdecWord(1)};
  ASSERT_GT(first.size(), opening.size());
  for (std::size_t k = 0; k < opening.size(); ++k) EXPECT_EQ(first[k].word, opening[k]) << k;
  int fieldDct = 0;
  int frameDct = 0;
  int motionTypeReads = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    for (std::size_t k = 0; k < r[i].issued.size(); ++k) {
      const std::uint32_t w = r[i].issued[k].word;
      if (opcodeOf(w) == IpuOpcode::kBdec) {
        EXPECT_EQ(w & 63, 0u) << "BDEC's FB";
        EXPECT_NE((w >> 16) & 31, 0u) << "BDEC's QSC";
        ((w >> 25) & 1 ? fieldDct : frameDct) += 1;
      }
      // After the macroblock_type VDEC of a motion-compensated macroblock: its 2-bit motion type.
      if (w == vdecWord(0, VdecTable::kMacroblockType) && k + 1 < r[i].issued.size() &&
          r[i].issued[k + 1].word == fdecWord(2)) {
        ++motionTypeReads;
      }
    }
  }
  EXPECT_GT(fieldDct, 0) << "no BDEC with DT = 1 in an interlaced stream";
  EXPECT_GT(frameDct, 0);
  EXPECT_GT(motionTypeReads, 0);
}

}  // namespace
}  // namespace vbim::ipu
