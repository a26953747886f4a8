// The block walker of the per-stage vectors (ipu/block_walker.hpp) against the decoder: the IDCT of
// every block it walks, put back into a picture, is the decoder's picture bit for bit, for every
// IDCT kind and every coding option an intra picture can use; so what the vlc.txt and idct.txt
// vectors show is what the decoder computes.
#include "ipu/block_walker.hpp"

#include <gtest/gtest.h>

#include <span>
#include <string>

#include "ipu/elementary_stream.hpp"
#include "ipu/idct_libmpeg2.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/quant_tables.hpp"
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

}  // namespace
}  // namespace vbim::ipu
