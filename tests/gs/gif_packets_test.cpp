// The GIF packets of `vbim config --gs-setup --format gif|c`, checked bit field by bit field: each
// expected 64-bit word is rebuilt here from the field layout the GS documents (T-GS; ps2sdk
// gif_tags.h GIF_SET_TAG, gs_gp.h GS_SET_BITBLTBUF / TRXPOS / TRXREG / TRXDIR / ALPHA), written
// out as (first bit, width) pairs, not from the model's own shifts.
#include "gs/gif_packets.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "gs/gs_timing.hpp"
#include "gs/vram_plan.hpp"

namespace vbim::gs {
namespace {

struct Field {
  int lsb;
  int bits;
  std::uint64_t value;
};

// Packs fields into a word, failing the test if a value does not fit its field or fields overlap.
std::uint64_t pack(std::initializer_list<Field> fields) {
  std::uint64_t word = 0;
  std::uint64_t used = 0;
  for (const Field& f : fields) {
    const std::uint64_t mask = f.bits == 64 ? ~0ull : ((1ull << f.bits) - 1);
    EXPECT_EQ(f.value & ~mask, 0u) << "value " << f.value << " does not fit " << f.bits << " bits at " << f.lsb;
    EXPECT_EQ(used & (mask << f.lsb), 0u) << "fields overlap at bit " << f.lsb;
    used |= mask << f.lsb;
    word |= (f.value & mask) << f.lsb;
  }
  return word;
}

// GIFtag low word: NLOOP 0-14, EOP 15, PRE 46, PRIM 47-57, FLG 58-59, NREG 60-63.
std::uint64_t tag(std::uint64_t nloop, std::uint64_t eop, std::uint64_t flg, std::uint64_t nreg) {
  return pack({{0, 15, nloop}, {15, 1, eop}, {46, 1, 0}, {47, 11, 0}, {58, 2, flg}, {60, 4, nreg}});
}
constexpr std::uint64_t kPacked = 0, kImage = 2, kAd = 0xE;

void expectQword(const Qword& q, std::uint64_t lo, std::uint64_t hi, const std::string& where) {
  EXPECT_EQ(q.lo, lo) << where << ": " << q.what << std::hex << " lo 0x" << q.lo << " expected 0x" << lo;
  EXPECT_EQ(q.hi, hi) << where << ": " << q.what << std::hex << " hi 0x" << q.hi << " expected 0x" << hi;
}

// The samples: a 256x256 lightmap and a 128x64 sky with the default platform config (VRAM: staging
// at page 382, block 12,224; sky staging at page 446, block 14,272: docs/porting.md).
std::vector<GifPacket> samplePackets(const GsParams& p, BlendSurface surface) {
  const VramLayout vram = planVram(p, 256, 256, SkyTexture{128, 64});
  return surface == BlendSurface::Sky ? surfacePackets(p, vram, surface, 128, 64)
                                      : surfacePackets(p, vram, surface, 256, 256);
}

TEST(GifPackets, MacroblockUploadOfTheSampleLightmap) {
  const GsParams p;
  const std::vector<GifPacket> packets = samplePackets(p, BlendSurface::Lightmap);
  ASSERT_EQ(packets.size(), 4u);
  const GifPacket& first = packets[0];
  ASSERT_EQ(first.qwords.size(), 6u);
  expectQword(first.qwords[0], tag(4, 0, kPacked, 1), kAd, "upload tag");
  // BITBLTBUF: SBP 0-13, SBW 16-21, SPSM 24-29, DBP 32-45, DBW 48-53, DPSM 56-61.
  expectQword(first.qwords[1], pack({{0, 14, 0}, {16, 6, 0}, {24, 6, 0}, {32, 14, 12224}, {48, 6, 4}, {56, 6, 0x00}}),
              0x50, "BITBLTBUF");
  // TRXPOS: SSAX 0-10, SSAY 16-26, DSAX 32-42, DSAY 48-58, DIR 59-60.
  expectQword(first.qwords[2], pack({{0, 11, 0}, {16, 11, 0}, {32, 11, 0}, {48, 11, 0}, {59, 2, 0}}), 0x51, "TRXPOS");
  // TRXREG: RRW 0-11, RRH 32-43.
  expectQword(first.qwords[3], pack({{0, 12, 16}, {32, 12, 16}}), 0x52, "TRXREG");
  expectQword(first.qwords[4], pack({{0, 2, 0}}), 0x53, "TRXDIR");      // XDIR 0: host to local
  expectQword(first.qwords[5], tag(64, 1, kImage, 0), 0, "IMAGE tag");  // 16 x 16 x 4 bytes / 16
  EXPECT_EQ(first.dataQwords(), 64);
  // The model charges the same sizes: gs.upload_setup_qwords, gs.macroblock_setup_qwords.
  EXPECT_EQ(first.setupQwords(), p.upload_setup_qwords);
  const GifPacket& next = packets[1];
  ASSERT_EQ(next.qwords.size(), 4u);
  EXPECT_EQ(next.setupQwords(), p.macroblock_setup_qwords);
  expectQword(next.qwords[0], tag(2, 0, kPacked, 1), kAd, "next tag");
  expectQword(next.qwords[1], pack({{32, 11, 16}, {48, 11, 0}}), 0x51, "TRXPOS of macroblock 1");
  expectQword(next.qwords[2], 0, 0x53, "TRXDIR");
  expectQword(next.qwords[3], tag(64, 1, kImage, 0), 0, "IMAGE tag");
}

TEST(GifPackets, DrawAndCopyDrawDifferOnlyInFix) {
  const std::vector<GifPacket> packets = samplePackets(GsParams{}, BlendSurface::Lightmap);
  const GifPacket& draw = packets[2];
  const GifPacket& copy = packets[3];
  ASSERT_EQ(draw.setupQwords(), kBlendDrawSetupQwords);
  ASSERT_EQ(copy.setupQwords(), kBlendDrawSetupQwords);
  expectQword(draw.qwords[0], tag(19, 1, kPacked, 1), kAd, "draw tag");
  // ALPHA_1 (0x42): A 0-1, B 2-3, C 4-5, D 6-7, FIX 32-39; A = Cs (0), B = Cd (1), C = FIX (2), D = Cd (1).
  const auto alpha = [](std::uint64_t fix) { return pack({{0, 2, 0}, {2, 2, 1}, {4, 2, 2}, {6, 2, 1}, {32, 8, fix}}); };
  for (std::size_t i = 0; i < draw.qwords.size(); ++i) {
    if (draw.qwords[i].hi == 0x42) {
      expectQword(draw.qwords[i], alpha(0x40), 0x42, "ALPHA_1 of the blend");
      expectQword(copy.qwords[i], alpha(0x80), 0x42, "ALPHA_1 of the copy");
    } else {
      expectQword(copy.qwords[i], draw.qwords[i].lo, draw.qwords[i].hi, "qword " + std::to_string(i));
    }
  }
  // Each A+D qword is the value and the register address (bits 64-71), in blendDrawSetup's order.
  const VramLayout vram = planVram(GsParams{}, 256, 256, SkyTexture{128, 64});
  const BlendDrawSetup setup = blendDrawSetup(blendDrawFor(vram, GsParams{}, BlendSurface::Lightmap, 256, 256, 0, 256));
  for (std::size_t i = 0; i < setup.size(); ++i) {
    expectQword(draw.qwords[i + 1], setup[i].value, setup[i].reg.address, std::string(setup[i].reg.name));
  }
}

TEST(GifPackets, SkyUploadGoesToTheSkyStagingArea) {
  GsParams p;
  p.upload_strategy = "ee-reorder";  // one raster transfer of the 128x64 picture
  const std::vector<GifPacket> packets = samplePackets(p, BlendSurface::Sky);
  ASSERT_EQ(packets.size(), 3u);  // no per-macroblock packet
  const GifPacket& up = packets[0];
  ASSERT_EQ(up.qwords.size(), 6u);
  expectQword(up.qwords[1], pack({{32, 14, 14272}, {48, 6, 2}, {56, 6, 0}}), 0x50, "sky BITBLTBUF");
  expectQword(up.qwords[3], pack({{0, 12, 128}, {32, 12, 64}}), 0x52, "sky TRXREG");
  expectQword(up.qwords[5], tag(128 * 64 * 4 / 16, 1, kImage, 0), 0, "sky IMAGE tag");
  EXPECT_EQ(packets[1].name, "sky_draw");
  EXPECT_EQ(packets[2].name, "sky_draw_copy");
}

// gs.texture_format = ct16: PSMCT16 (0x02) in BITBLTBUF.DPSM, FRAME_1.PSM and TEX0_1.PSM, half the
// pixels' qwords, and TEXA, DIMX and DTHE before PRIM (DTHE = 0 in the copy); VRAM in 64x64 pages.
TEST(GifPackets, SixteenBitPathWritesPsmct16TexaDimxAndDthe) {
  GsParams p;
  p.texture_format = "ct16";
  const VramLayout vram = planVram(p, 256, 256, SkyTexture{128, 64});
  EXPECT_EQ(vram.region("lightmap").pages, 16);
  EXPECT_EQ(vram.region("staging").firstPage, 366);  // block 11,712
  const std::vector<GifPacket> packets = surfacePackets(p, vram, BlendSurface::Lightmap, 256, 256);
  ASSERT_EQ(packets.size(), 4u);
  expectQword(packets[0].qwords[1], pack({{32, 14, 11712}, {48, 6, 4}, {56, 6, 0x02}}), 0x50, "BITBLTBUF");
  expectQword(packets[0].qwords[5], tag(32, 1, kImage, 0), 0, "IMAGE tag");  // 16 x 16 x 2 bytes / 16
  const GifPacket& draw = packets[2];
  const GifPacket& copy = packets[3];
  ASSERT_EQ(draw.setupQwords(), kBlendDrawSetupQwords16);
  ASSERT_EQ(draw.setupQwords(), 23);
  expectQword(draw.qwords[0], tag(22, 1, kPacked, 1), kAd, "draw tag");
  // FRAME_1: FBP 0-8, FBW 16-21, PSM 24-29, FBMSK 32-63; TEX0_1: TBP0 0-13, TBW 14-19, PSM 20-25, TW 26-29,
  // TH 30-33, TCC 34, TFX 35-36.
  expectQword(draw.qwords[2], pack({{0, 9, 350}, {16, 6, 4}, {24, 6, 0x02}, {32, 32, 0}}), 0x4C, "FRAME_1");
  expectQword(draw.qwords[5],
              pack({{0, 14, 11712}, {14, 6, 4}, {20, 6, 0x02}, {26, 4, 8}, {30, 4, 8}, {34, 1, 1}, {35, 2, 0}}), 0x06,
              "TEX0_1");
  // TEXA (0x3B): TA0 0-7, AEM 15, TA1 32-39; DIMX (0x44); DTHE (0x45) bit 0; then PRIM.
  expectQword(draw.qwords[14], pack({{0, 8, 0x80}, {15, 1, 0}, {32, 8, 0x40}}), 0x3B, "TEXA");
  EXPECT_EQ(draw.qwords[15].hi, 0x44u);
  expectQword(draw.qwords[16], 1, 0x45, "DTHE of the blend");
  expectQword(copy.qwords[16], 0, 0x45, "DTHE of the copy");
  EXPECT_EQ(draw.qwords[17].hi, 0x00u) << "PRIM follows";
  for (std::size_t i = 0; i < draw.qwords.size(); ++i) {
    if (draw.qwords[i].hi != 0x42 && draw.qwords[i].hi != 0x45) {
      expectQword(copy.qwords[i], draw.qwords[i].lo, draw.qwords[i].hi, "qword " + std::to_string(i));
    }
  }
  // FBMSK of gs.alpha_write = keep masks the alpha bit only (bit 31: PSMCT16's A).
  p.alpha_write = "keep";
  const GifPacket keep = surfacePackets(p, vram, BlendSurface::Lightmap, 256, 256)[2];
  expectQword(keep.qwords[2], pack({{0, 9, 350}, {16, 6, 4}, {24, 6, 0x02}, {32, 32, 0x80000000}}), 0x4C,
              "FRAME_1 keeping alpha");
  // The model charges the three extra writes on the GIF: 3 qwords, 6 ticks at 8 bytes a tick.
  GsParams p32;
  p.alpha_write = "source";
  EXPECT_EQ(GsTiming(p).spriteDraw(256, 256) - GsTiming(p32).spriteDraw(256, 256), 3 * 16 / 8);
}

// NLOOP has 15 bits: a 1024x1024 raster upload (262,144 qwords) takes nine IMAGE GIFtags.
TEST(GifPackets, AnImageLargerThanOneTagIsSplit) {
  const VramRegion staging{"staging", Psm::Ct32, 1024, 1024, 0, 512};  // all of VRAM
  const GifPacket up = uploadPacket(staging, 0, 0, 1024, 1024, 4, true, "big", "");
  ASSERT_EQ(up.qwords.size(), 5u + 9u);
  for (int i = 0; i < 8; ++i) expectQword(up.qwords[5 + i], tag(0x7FFF, 0, kImage, 0), 0, "chunk");
  expectQword(up.qwords[13], tag(262144 - 8 * 0x7FFF, 1, kImage, 0), 0, "last chunk");
  EXPECT_EQ(up.dataQwords(), 262144);
}

}  // namespace
}  // namespace vbim::gs
