// The 16-bit lightmap path (gs.texture_format = ct16, gs/blend16.hpp): the channel arithmetic in the
// GS's order (blend, DIMX, wrap, saturate, top 5 bits), the DIMX register's layout, the staging
// texture as the IPU's RGB16 output, and the tiled blender's 16-bit path against a plain blend of
// the whole picture (convergence skipping and the hash chain change no byte).
#include "gs/blend16.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "gs/tiled_blender.hpp"
#include "ipu/csc.hpp"
#include "ipu/frame_store.hpp"

namespace vbim::gs {
namespace {

BlendSpec spec16(int fix, bool dither, ColClamp c = ColClamp::Clamp, AlphaWrite a = AlphaWrite::Source) {
  BlendSpec s = makeBlendSpec(fix, c, a);
  s.psmct16 = true;
  s.dither = dither;
  return s;
}

TEST(Blend16, ChannelArithmeticInTheGsOrder) {
  // A copy without DTHE keeps a 5-bit value; with it, a negative DIMX entry would drop it a level
  // (why the copy draw turns DTHE off).
  EXPECT_EQ(blend16Channel(248, 0, 0x80, 0, ColClamp::Clamp), 248);
  EXPECT_EQ(blend16Channel(248, 0, 0x80, -4, ColClamp::Clamp), 240);
  EXPECT_EQ(blend16Channel(248, 0, 0x80, 3, ColClamp::Clamp), 248);
  // At FIX 0x40 a channel one level (8) below its target stays there whatever the dither ...
  for (int d = -4; d <= 3; ++d) EXPECT_EQ(blend16Channel(16, 8, 0x40, d, ColClamp::Clamp), 8) << d;
  // ... and one level above reaches it.
  for (int d = -4; d <= 3; ++d) EXPECT_EQ(blend16Channel(8, 16, 0x40, d, ColClamp::Clamp), 8) << d;
  // Two levels below: half way is exactly one level up, which a negative entry rounds back down.
  EXPECT_EQ(blend16Channel(24, 8, 0x40, 0, ColClamp::Clamp), 16);
  EXPECT_EQ(blend16Channel(24, 8, 0x40, -1, ColClamp::Clamp), 8);
  // DIMX is added before COLCLAMP: clamped at 0, or wrapped to 252 and kept as 248.
  EXPECT_EQ(blend16Channel(0, 0, 0x40, -4, ColClamp::Clamp), 0);
  EXPECT_EQ(blend16Channel(0, 0, 0x40, -4, ColClamp::Wrap), 248);
  EXPECT_EQ(blend16Channel(248, 248, 0x40, 3, ColClamp::Clamp), 248);
  // Every result is a stored 5-bit value.
  for (int cs = 0; cs < 256; cs += 8)
    for (int cd = 0; cd < 256; cd += 8)
      for (int d = -4; d <= 3; ++d) EXPECT_EQ(blend16Channel(cs, cd, 0x40, d, ColClamp::Clamp) & 7, 0);
}

// GS_SET_DIMX(4,2,5,3, 0,6,1,7, 5,3,4,2, 1,7,0,6): entry (row, column) in bits 16 * row + 4 * column,
// 3-bit two's complement, as ps2sdk's gs_gp.h lays it out.
TEST(Blend16, DimxRegisterHasTheUsualMatrix) {
  const int args[16] = {4, 2, 5, 3, 0, 6, 1, 7, 5, 3, 4, 2, 1, 7, 0, 6};
  std::uint64_t v = 0;
  for (int i = 0; i < 16; ++i) v |= static_cast<std::uint64_t>(args[i]) << (16 * (i / 4) + 4 * (i % 4));
  EXPECT_EQ(dimxRegister(), v);
  EXPECT_EQ(dimxRegister(), 0x6071243571603524u);
  for (int i = 0; i < 16; ++i) {
    const int signedValue = args[i] >= 4 ? args[i] - 8 : args[i];
    EXPECT_EQ(kDimx[static_cast<std::size_t>(i / 4)][static_cast<std::size_t>(i % 4)], signedValue) << i;
  }
  // TEXA: TA0 bits 0-7, AEM bit 15, TA1 bits 32-39.
  EXPECT_EQ(kTexa16, 0x80u | (0x40ull << 32));
}

// The staging texture is the IPU's RGB16 output (OFM = 1, DTE = 1) as TEXA expands it: computed from
// the RGB32 output here, by ipu::convertToRgb16 from the YCbCr there, for a picture of noise with
// SETTH thresholds (so the alpha bit is exercised).
TEST(Blend16, StagingIsTheIpusDitheredRgb16) {
  ipu::FrameStore fs;
  fs.reset(3, 2);  // 48x32
  std::mt19937 rng(7);
  for (auto* plane : {&fs.y, &fs.cb, &fs.cr})
    for (auto& b : *plane) b = static_cast<std::uint8_t>(rng());
  const ipu::CscThresholds th{40, 120};
  Rgba8Image rgb32;
  ipu::convertToRgba32(fs, 48, 32, th, rgb32);
  std::vector<std::uint16_t> rgb16;
  ipu::convertToRgb16(fs, 48, 32, th, true, rgb16);
  Rgba8Image staging;
  staging16FromRgb32(rgb32, staging);
  int translucent = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 48; ++x) {
      const std::uint8_t* p = staging.row(y) + 4 * x;
      const std::uint16_t t = rgb16[static_cast<std::size_t>(y) * 48 + x];
      // TEXA: A = 0 -> TA0 = 0x80, A = 1 -> TA1 = 0x40; colours the 5-bit field << 3.
      EXPECT_EQ(p[0], (t & 0x1F) << 3) << x << "," << y;
      EXPECT_EQ(p[1], ((t >> 5) & 0x1F) << 3) << x << "," << y;
      EXPECT_EQ(p[2], ((t >> 10) & 0x1F) << 3) << x << "," << y;
      EXPECT_EQ(p[3], (t & 0x8000) ? 0x40 : 0x80) << x << "," << y;
      translucent += (t & 0x8000) ? 1 : 0;
    }
  }
  EXPECT_GT(translucent, 0) << "the thresholds set no alpha bit: the test proves less than it says";
}

Rgba8Image noise16(int w, int h, unsigned seed) {
  Rgba8Image img(w, h);
  std::mt19937 rng(seed);
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = static_cast<std::uint8_t>(i % 4 == 3 ? ((rng() & 1) ? 0x80 : 0x40) : (rng() & 0xF8));
  return img;
}

// The tiled blender's 16-bit path, with and without convergence skipping and the hash chain, gives
// the bytes of blend16Rect over the whole picture, vsync after vsync, across a source change.
TEST(Blend16, TiledBlenderEqualsAWholePictureBlend) {
  const int w = 160, h = 96;  // partial tiles in both directions
  const Rgba8Image a = noise16(w, h, 1), b = noise16(w, h, 2);
  Rgba8Image plain(w, h), tiled(w, h), hashed(w, h);
  TiledBlender tb(w, h, scalarKernels(), true), th(w, h, scalarKernels(), true, true);
  for (int v = 0; v < 40; ++v) {
    const Rgba8Image& src = v < 20 ? a : b;
    const BlendSpec spec = v == 0 ? spec16(0x80, false) : spec16(0x40, true);
    const int pop = blend16Rect(plain.pixels.data(), static_cast<std::size_t>(w) * 4, src.pixels.data(),
                                static_cast<std::size_t>(w) * 4, static_cast<std::size_t>(w),
                                static_cast<std::size_t>(h), 0, 0, spec);
    const TiledBlender::Result r = tb.blend(tiled, src, spec, v < 20 ? 1 : 2);
    th.blend(hashed, src, spec, v < 20 ? 1 : 2);
    ASSERT_EQ(tiled.pixels, plain.pixels) << "vsync " << v;
    ASSERT_EQ(hashed.pixels, plain.pixels) << "vsync " << v;
    EXPECT_EQ(r.pop, pop) << "vsync " << v;
    HashChain fresh;
    fresh.addHeader(w, h);
    fresh.addBytes(hashed.pixels.data(), hashed.pixels.size());
    const HashChain& kept = th.hashChain(hashed);
    ASSERT_EQ(kept.count, fresh.count) << "vsync " << v;
    for (int l = 0; l < 4; ++l) ASSERT_EQ(kept.lanes[l], fresh.lanes[l]) << "vsync " << v << " lane " << l;
  }
  // The blend settles (a stall below the target) and the skipping found it.
  EXPECT_EQ(tb.blend(tiled, b, spec16(0x40, true), 2).tilesSkipped, tb.tilesX() * tb.tilesY());
}

}  // namespace
}  // namespace vbim::gs
