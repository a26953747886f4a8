// The block walker of the per-stage vectors (ipu/block_walker.hpp) against the decoder: the IDCT of
// every block it walks, put back into a picture, is the decoder's picture bit for bit, for every
// IDCT kind and every coding option an intra picture can use; so what the vlc.txt and idct.txt
// vectors show is what the decoder computes.
#include "ipu/block_walker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <span>
#include <string>

#include "ipu/elementary_stream.hpp"
#include "ipu/idct_libmpeg2.hpp"
#include "ipu/inter_vlc.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/kernels.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/quant_tables.hpp"
#include "tests/ipu/support/field_picture_writer.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using testing::Content;
using testing::EncodeOptions;

bool samePlanes(const FrameStore& a, const FrameStore& b) {
  return a.mbWidth == b.mbWidth && a.mbHeight == b.mbHeight && a.y == b.y && a.cb == b.cb && a.cr == b.cr;
}

// Walks and decodes every picture of the stream with every IDCT kind; returns the number of blocks
// with an escape code and with field DCT seen, so a case shows it exercises what it names.
struct Seen {
  int escapes = 0;
  int fieldDct = 0;
  int blocks = 0;
};

Seen checkStream(const std::vector<std::uint8_t>& es, const std::string& what) {
  Seen seen;
  for (const IdctKind kind : kAllIdctKinds) {
    DecoderOptions options;
    options.idct = kind;
    Decoder dec(options);
    int index = 0;
    for (const AccessUnit& au : splitAccessUnits(es)) {
      const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size));
      if (!r.produced) continue;
      EXPECT_TRUE(r.clean()) << what << ": " << r.describe();
      WalkedPicture pic;
      std::string error;
      if (!walkIntraPicture(es, pic, error, index)) {
        ADD_FAILURE() << what << " picture " << index << ": " << error;
        return seen;
      }
      EXPECT_EQ(static_cast<int>(pic.macroblocks.size()), pic.mbWidth * pic.mbHeight) << what;
      EXPECT_TRUE(samePlanes(assembleIntraPicture(pic, kind), dec.frame()))
          << what << " picture " << index << ", IDCT " << idctKindName(kind);
      if (kind == IdctKind::Pcsx2) {
        for (const WalkedMacroblock& mb : pic.macroblocks) {
          seen.fieldDct += mb.fieldDct ? 1 : 0;
          for (const WalkedBlock& b : mb.blocks) {
            ++seen.blocks;
            for (const RunLevel& rl : b.ac) seen.escapes += rl.escape ? 1 : 0;
          }
        }
      }
      ++index;
    }
    EXPECT_GT(index, 0) << what;
  }
  return seen;
}

TEST(BlockWalker, AssemblingItsIdctOutputsGivesTheDecodersPicture) {
  struct Case {
    const char* name;
    EncodeOptions o;
  };
  std::vector<Case> cases;
  EncodeOptions base;
  base.width = 64;
  base.height = 48;
  base.frames = 2;
  cases.push_back({"default", base});
  EncodeOptions busy = base;
  busy.content = Content::kNoise;
  busy.quantiser = 1;
  cases.push_back({"noise at quantiser 1 (escapes, saturation)", busy});
  EncodeOptions opts = base;
  opts.content = Content::kBusy;
  opts.intraVlc = true;
  opts.alternateScan = true;
  opts.nonLinearQuant = true;
  opts.dcPrecision = 2;
  opts.customMatrix = true;
  cases.push_back({"intra_vlc_format, alternate scan, non-linear quantiser, 10-bit DC, own matrix", opts});
  EncodeOptions field = base;
  field.content = Content::kInterlaced;
  field.interlacedDct = true;
  cases.push_back({"field DCT", field});
  EncodeOptions mpeg1 = base;
  mpeg1.mpeg1 = true;
  mpeg1.content = Content::kBusy;
  mpeg1.quantiser = 2;
  cases.push_back({"MPEG-1", mpeg1});
  for (const Case& c : cases) {
    const Seen seen = checkStream(testing::encodeIntra(c.o), c.name);
    EXPECT_GT(seen.blocks, 0) << c.name;
    if (c.o.interlacedDct) {
      EXPECT_GT(seen.fieldDct, 0) << c.name << ": no field DCT macroblock";
    }
    if (c.o.content == Content::kNoise) {
      EXPECT_GT(seen.escapes, 0) << c.name << ": no escape code";
    }
  }
}

// A block's entries agree with each other: the quantised levels sit where the scan puts the runs,
// and the DC differential moves the predictor.
TEST(BlockWalker, RunLevelPairsPlaceTheQuantisedCoefficients) {
  EncodeOptions o;
  o.content = Content::kBusy;
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  WalkedPicture pic;
  std::string error;
  ASSERT_TRUE(walkIntraPicture(es, pic, error)) << error;
  int pred[3] = {128, 128, 128};  // 8-bit DC precision: the reset value (§7.2.1)
  int lastRow = -1;
  for (const WalkedMacroblock& mb : pic.macroblocks) {
    if (mb.mbY != lastRow) pred[0] = pred[1] = pred[2] = 128;  // a slice per row
    lastRow = mb.mbY;
    for (int b = 0; b < 6; ++b) {
      const WalkedBlock& blk = mb.blocks[static_cast<std::size_t>(b)];
      const int cc = b < 4 ? 0 : b - 3;
      pred[cc] += blk.dcDifferential;
      EXPECT_EQ(blk.quantised[0], pred[cc]);
      std::array<std::int16_t, 64> placed{};
      placed[0] = blk.quantised[0];
      int i = 0;
      for (const RunLevel& rl : blk.ac) {
        i += rl.run + 1;
        ASSERT_LT(i, 64);
        placed[kZigzagScan[static_cast<std::size_t>(i)]] = static_cast<std::int16_t>(rl.level);
      }
      EXPECT_EQ(placed, blk.quantised);
    }
  }
}

TEST(BlockWalker, RefusesAPredictedPictureNamingIt) {
  EncodeOptions o;
  o.gopSize = 3;
  o.frames = 3;
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  WalkedPicture pic;
  std::string error;
  EXPECT_TRUE(walkIntraPicture(es, pic, error, 0)) << error;
  EXPECT_FALSE(walkIntraPicture(es, pic, error, 1));
  EXPECT_NE(error.find("not a 4:2:0 intra frame picture (picture_coding_type 2"), std::string::npos) << error;
  EXPECT_FALSE(walkIntraPicture(es, pic, error, 7));
  EXPECT_NE(error.find("no slice of picture 7"), std::string::npos) << error;
}

// The walk of every picture of `es` (all kinds, frames and fields) against the decoder's macroblock
// trace: the same macroblocks at the same addresses with the same bits, BDEC bits, skips before
// them, and for P and B pictures the EE's VDEC and FDEC reads counted as the BDEC flow charges them
// (ipu/bdec_flow.hpp). Returns how many walked macroblocks were non-intra, so a case shows it
// walks what it names.
struct InterSeen {
  int pictures = 0;
  int nonIntra = 0;
  int nonIntraBlocks = 0;
  int skipped = 0;
  int fieldPictures = 0;
  int predicted = 0;  // P and B pictures
};

InterSeen checkAgainstTrace(const std::vector<std::uint8_t>& es, const std::string& what) {
  InterSeen seen;
  DecoderOptions options;
  options.recordMacroblocks = true;
  Decoder dec(options);
  std::vector<MacroblockBits> trace;
  std::vector<int> traceCodingType;
  for (const AccessUnit& au : splitAccessUnits(es)) {
    const PictureReport r = dec.decode(std::span(es).subspan(au.offset, au.size));
    EXPECT_TRUE(r.clean()) << what << ": " << r.describe();
    trace.insert(trace.end(), dec.macroblockTrace().begin(), dec.macroblockTrace().end());
  }
  std::vector<WalkedMacroblock> walked;
  std::vector<int> codingType;
  for (int index = 0;; ++index) {
    WalkedPicture pic;
    std::string error;
    if (!walkPicture(es, pic, error, index)) {
      EXPECT_NE(error.find("no slice of picture"), std::string::npos) << what << " picture " << index << ": " << error;
      break;
    }
    ++seen.pictures;
    seen.fieldPictures += pic.pictureStructure != 3 ? 1 : 0;
    seen.predicted += pic.codingType != 1 ? 1 : 0;
    for (WalkedMacroblock& mb : pic.macroblocks) {
      codingType.push_back(pic.codingType);
      walked.push_back(std::move(mb));
    }
  }
  EXPECT_EQ(walked.size(), trace.size()) << what;
  for (std::size_t i = 0; i < std::min(walked.size(), trace.size()); ++i) {
    const WalkedMacroblock& w = walked[i];
    const MacroblockBits& t = trace[i];
    SCOPED_TRACE(what + ", macroblock " + std::to_string(i) + " (address " + std::to_string(t.address) + ")");
    if (static_cast<std::uint32_t>(w.address) != t.address) {
      ADD_FAILURE() << "walked address " << w.address;
      return seen;
    }
    EXPECT_EQ(w.bits, t.bits);
    EXPECT_EQ(w.sliceStart, t.sliceStart);
    if (codingType[i] == 1) continue;  // the intra slice decoder records no reads
    EXPECT_EQ(w.skippedBefore, t.skippedBefore);
    EXPECT_EQ(w.intra || w.codedBlockPattern != 0, t.bdec);
    EXPECT_EQ(t.bdec ? w.blockBits : 0, t.blockBits);
    int vdec = 0;
    int fdec = 0;
    for (const std::uint32_t word : w.eeWords) {
      vdec += opcodeOf(word) == IpuOpcode::kVdec ? 1 : 0;
      fdec += opcodeOf(word) == IpuOpcode::kFdec ? 1 : 0;
    }
    // The trace's FDECs leave out the slice header's four (kSliceHeaderFdec).
    EXPECT_EQ(vdec, t.vdec);
    EXPECT_EQ(fdec - (w.sliceStart ? 4 : 0), t.fdec);
    seen.skipped += w.skippedBefore;
    if (!w.intra) {
      ++seen.nonIntra;
      for (const WalkedBlock& b : w.blocks) seen.nonIntraBlocks += b.coded ? 1 : 0;
    }
  }
  return seen;
}

TEST(BlockWalker, WalksPAndBPicturesAndFieldsAsTheDecoderReadsThem) {
  struct Case {
    const char* name;
    EncodeOptions o;
  };
  std::vector<Case> cases;
  EncodeOptions gop;
  gop.width = 96;
  gop.height = 64;
  gop.frames = 7;
  gop.gopSize = 6;
  gop.bFrames = 2;
  gop.content = Content::kPan;
  cases.push_back({"I, P and B frame pictures", gop});
  EncodeOptions interlaced = gop;
  interlaced.interlacedDct = true;
  interlaced.interlacedMe = true;
  interlaced.content = Content::kInterlaced;
  cases.push_back({"field prediction and field DCT", interlaced});
  EncodeOptions mpeg1 = gop;
  mpeg1.mpeg1 = true;
  cases.push_back({"MPEG-1 P and B", mpeg1});
  EncodeOptions busy = gop;
  busy.content = Content::kNoise;
  busy.quantiser = 2;
  busy.nonLinearQuant = true;
  busy.customMatrix = true;
  busy.customInterMatrix = true;
  cases.push_back({"noise, non-linear quantiser, own matrices", busy});
  for (const Case& c : cases) {
    const InterSeen seen = checkAgainstTrace(testing::encodeIntra(c.o), c.name);
    EXPECT_EQ(seen.pictures, c.o.frames) << c.name;
    EXPECT_GT(seen.predicted, 0) << c.name;
    EXPECT_GT(seen.nonIntraBlocks, 0) << c.name;
  }
  // What libavcodec never writes: field pictures, 16x8 and dual prime, skips in fields,
  // concealment vectors (tests/ipu/support/field_picture_writer.hpp).
  for (const bool fields : {true, false}) {
    testing::FieldStreamOptions o;
    o.fieldPictures = fields;
    o.pictures = 2;
    o.concealmentVectors = true;
    const InterSeen seen = checkAgainstTrace(testing::makeFieldStream(o), fields ? "field pictures" : "dual prime");
    EXPECT_GT(seen.nonIntra, 0);
    if (fields) {
      EXPECT_EQ(seen.fieldPictures, 4);
      EXPECT_GT(seen.skipped, 0);
    }
  }
}

// A non-intra block (§7.4.2.3): F = ((2 QF + sign(QF)) x W x quantiser_scale) / 32 with the
// non-intra matrix, saturated, mismatch control; its runs count from scan position 0.
TEST(BlockWalker, DequantisesNonIntraBlocksWithTheNonIntraTerm) {
  EncodeOptions o;
  o.width = 64;
  o.height = 48;
  o.frames = 3;
  o.gopSize = 3;
  o.content = Content::kPan;
  o.quantiser = 2;
  o.customMatrix = true;
  o.customInterMatrix = true;
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  WalkedPicture pic;
  std::string error;
  ASSERT_TRUE(walkPicture(es, pic, error, 1)) << error;
  ASSERT_EQ(pic.codingType, 2);
  // The encoder's own non-intra matrix, not the default flat 16.
  EXPECT_NE(std::count(pic.nonIntraMatrix.begin(), pic.nonIntraMatrix.end(), std::uint8_t{16}), 64);
  int blocks = 0;
  for (const WalkedMacroblock& mb : pic.macroblocks) {
    if (mb.intra) continue;
    const int scale = quantiserScale(false, pic.qScaleType, mb.quantiserScaleCode);
    for (const WalkedBlock& b : mb.blocks) {
      if (!b.coded) continue;
      ++blocks;
      EXPECT_FALSE(b.intra);
      std::array<std::int16_t, 64> f{};
      int i = -1;
      int sum = 0;
      for (const RunLevel& rl : b.ac) {
        i += rl.run + 1;
        ASSERT_LT(i, 64);
        const std::size_t pos = kZigzagScan[static_cast<std::size_t>(i)];
        EXPECT_EQ(b.quantised[pos], rl.level);
        const int mag = std::abs(rl.level);
        const int v = std::min((2 * mag + 1) * pic.nonIntraMatrix[pos] * scale / 32, rl.level < 0 ? 2048 : 2047);
        f[pos] = static_cast<std::int16_t>(rl.level < 0 ? -v : v);
        sum += f[pos];
      }
      if ((sum & 1) == 0) f[63] = static_cast<std::int16_t>(f[63] ^ 1);
      EXPECT_EQ(f, b.dequantised);
    }
  }
  EXPECT_GT(blocks, 0);
}

// A non-intra block's residual (nonIntraResidual: what idct.txt lists) is what the model's add
// kernel adds to a prediction, for every IDCT kind, the decoders' shortcut for a block coded with
// its first coefficient alone included.
TEST(BlockWalker, NonIntraResidualIsWhatTheAddKernelAdds) {
  EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = 7;
  o.gopSize = 6;
  o.bFrames = 2;
  o.quantiser = 3;
  o.content = Content::kPan;
  const std::vector<std::uint8_t> es = testing::encodeIntra(o);
  int blocks = 0;
  int firstOnly = 0;
  for (int index = 0;; ++index) {
    WalkedPicture pic;
    std::string error;
    if (!walkPicture(es, pic, error, index)) break;
    for (const WalkedMacroblock& mb : pic.macroblocks) {
      for (const WalkedBlock& b : mb.blocks) {
        if (!b.coded || b.intra) continue;
        ++blocks;
        firstOnly += b.firstOnly() ? 1 : 0;
        for (const IdctKind kind : kAllIdctKinds) {
          std::int16_t residual[64];
          nonIntraResidual(kind, b, residual);
          std::uint8_t dst[64];
          std::fill(std::begin(dst), std::end(dst), std::uint8_t{128});
          const unsigned rowMask = 0xFFu | (b.firstOnly() ? kIdctFirstOnly : 0u);
          scalarKernels().idctOf(kind).add(b.dequantised.data(), rowMask, 0xFFu, dst, 8);
          for (int i = 0; i < 64; ++i) {
            ASSERT_EQ(dst[i], std::clamp(128 + residual[i], 0, 255)) << idctKindName(kind) << " sample " << i;
          }
        }
      }
    }
  }
  EXPECT_GT(blocks, 0);
  EXPECT_GT(firstOnly, 0) << "no block coded with its first coefficient alone";
  // Every first-only block a stream can hold: F[0][0] = dc with mismatch control's F[7][7]. The
  // shortcut gives the full transform's values for each of them (so idct.txt's result, the IDCT of
  // `in`, is what the decoder adds, and a port may take either path).
  for (int dc = -2048; dc <= 2047; ++dc) {
    WalkedBlock b;
    b.intra = false;
    b.ac.push_back(RunLevel{0, 1, false});
    b.dequantised[0] = static_cast<std::int16_t>(dc);
    if ((dc & 1) == 0) b.dequantised[63] = 1;  // §7.4.4: an even sum toggles F[7][7]
    for (const IdctKind kind : kAllIdctKinds) {
      std::int16_t residual[64];
      nonIntraResidual(kind, b, residual);
      std::int16_t full[64];
      idctResult(kind, b.dequantised.data(), full);
      ASSERT_TRUE(std::equal(residual, residual + 64, full)) << idctKindName(kind) << " dc " << dc;
      std::uint8_t dst[64];
      std::fill(std::begin(dst), std::end(dst), std::uint8_t{128});
      scalarKernels().idctOf(kind).add(b.dequantised.data(), 0xFFu | kIdctFirstOnly, 0xFFu, dst, 8);
      for (int i = 0; i < 64; ++i) {
        ASSERT_EQ(dst[i], std::clamp(128 + residual[i], 0, 255)) << idctKindName(kind) << " dc " << dc;
      }
    }
  }
}

// The EE's reads of a P macroblock, in libmpeg's order (_mpeg12_dec_mb): VDEC of the address
// increment and macroblock_type, then the fixed-length fields with FB = their widths.
TEST(BlockWalker, RecordsTheEesReadsWithTheirWidths) {
  testing::FieldStreamOptions o;
  o.fieldPictures = false;
  o.dualPrime = false;
  const std::vector<std::uint8_t> es = testing::makeFieldStream(o);
  WalkedPicture pic;
  std::string error;
  ASSERT_TRUE(walkPicture(es, pic, error, 1)) << error;
  ASSERT_EQ(pic.codingType, 2);
  int checked = 0;
  for (const WalkedMacroblock& mb : pic.macroblocks) {
    std::vector<std::uint32_t> words = mb.eeWords;
    if (mb.sliceStart) {
      ASSERT_GE(words.size(), 4u);
      EXPECT_EQ(words[0], fdecWord(0));  // the start code's peek
      EXPECT_EQ(words[1], fdecWord(32));
      EXPECT_EQ(words[2], fdecWord(5));  // quantiser_scale_code
      EXPECT_EQ(words[3], fdecWord(1));  // extra_bit_slice
      words.erase(words.begin(), words.begin() + 4);
    }
    std::size_t k = 0;
    while (k < words.size() && words[k] == vdecWord(0, VdecTable::kAddressIncrement)) ++k;
    ASSERT_GE(k, 1u);
    ASSERT_LT(k, words.size());
    EXPECT_EQ(words[k++], vdecWord(0, VdecTable::kMacroblockType));
    if (mb.motionType != 0) {
      EXPECT_EQ(words[k++], fdecWord(2));
    }
    if ((mb.type & (kMbIntra | kMbPattern)) && !pic.mpeg1) {
      // frame_pred_frame_dct = 0 in these pictures: dct_type follows.
      EXPECT_EQ(words[k++], fdecWord(1));
    }
    if (mb.type & kMbQuant) {
      EXPECT_EQ(words[k++], fdecWord(5));
    }
    for (; k < words.size(); ++k) {
      const IpuOpcode op = opcodeOf(words[k]);
      EXPECT_TRUE(op == IpuOpcode::kVdec || op == IpuOpcode::kFdec);
      if (op == IpuOpcode::kFdec) {
        EXPECT_LE(words[k] & 63, 8u);  // a field select, residual or marker
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace vbim::ipu
