#include "gs/draw_setup.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gs/error.hpp"
#include "gs/gs_timing.hpp"
#include "gs/presenter.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::gs {
namespace {

std::uint64_t valueOf(const BlendDrawSetup& s, std::string_view name, int occurrence = 0) {
  for (const RegisterWrite& w : s) {
    if (w.reg.name == name && occurrence-- == 0) return w.value;
  }
  ADD_FAILURE() << name << " is not in the blend draw's setup";
  return 0;
}

// The sample streams' 256x256 lightmap with the default platform config.
BlendDrawSetup sampleSetup(const GsParams& p = GsParams{}, int y0 = 0, int y1 = 256) {
  const VramLayout vram = planVram(p, 256, 256);
  return blendDrawSetup(blendDrawFor(vram, p, BlendSurface::Lightmap, 256, 256, y0, y1));
}

// The sample streams' 128x64 sky, in the console's plan with their lightmap.
BlendDrawSetup sampleSkySetup(const GsParams& p = GsParams{}, int y0 = 0, int y1 = 64) {
  const VramLayout vram = planVram(p, 256, 256, SkyTexture{128, 64});
  return blendDrawSetup(blendDrawFor(vram, p, BlendSurface::Sky, 128, 64, y0, y1));
}

TEST(BlendDrawSetup, WritesEveryRegisterTheBlendDependsOn) {
  std::set<std::string_view> names;
  for (const GsRegister& r : kBlendDrawRegisters) names.insert(r.name);
  for (const char* needed : {"TEXFLUSH", "FRAME_1", "ZBUF_1", "TEST_1", "TEX0_1", "TEX1_1", "CLAMP_1", "ALPHA_1",
                             "PABE", "FBA_1", "COLCLAMP", "SCISSOR_1", "XYOFFSET_1", "PRIM", "RGBAQ", "UV", "XYZ2"}) {
    EXPECT_TRUE(names.count(needed)) << needed;
  }
  // The GIFtag plus one qword per write; the draw's GIF time follows from it.
  EXPECT_EQ(kBlendDrawSetupQwords, 20);
  GsParams p;
  p.page_break_overhead_pct = 0;
  EXPECT_EQ(GsTiming(p).spriteDraw(1, 1), kBlendDrawSetupQwords * 16 / p.gif_bytes_per_tick + 1);
}

TEST(BlendDrawSetup, ValuesForTheSampleStreams) {
  const BlendDrawSetup s = sampleSetup();
  // VRAM: frames at pages 0 and 140, Z16 at 280, lightmap at 350, staging at 382 (block 12,224).
  EXPECT_EQ(valueOf(s, "FRAME_1"), 0x0004015Eu);         // FBP 350, FBW 4, PSMCT32, FBMSK 0
  EXPECT_EQ(valueOf(s, "ZBUF_1"), 0x0000000102000118u);  // ZBP 280, PSMZ16, ZMSK
  EXPECT_EQ(valueOf(s, "TEST_1"), 0x00030000u);          // ZTE 1, ZTST ALWAYS
  EXPECT_EQ(valueOf(s, "TEX0_1"), 0x0000000620012FC0u);  // TBP0 12,224, TBW 4, TW = TH = 8, TCC 1
  EXPECT_EQ(valueOf(s, "CLAMP_1"), 0x5u);
  EXPECT_EQ(valueOf(s, "ALPHA_1"), 0x0000004000000064u);  // (Cs - Cd) * 0x40 + Cd
  EXPECT_EQ(valueOf(s, "COLCLAMP"), 1u);
  EXPECT_EQ(valueOf(s, "SCISSOR_1"), 0x00FF000000FF0000u);
  EXPECT_EQ(valueOf(s, "PRIM"), 0x156u);
  EXPECT_EQ(valueOf(s, "RGBAQ"), 0x3F80000080808080u);
  EXPECT_EQ(valueOf(s, "UV", 1), 0x10001000u);  // (256, 256) in 10.4
  EXPECT_EQ(valueOf(s, "XYZ2", 1), 0x10001000u);
  for (const char* zero : {"TEXFLUSH", "TEX1_1", "PABE", "FBA_1", "XYOFFSET_1"}) EXPECT_EQ(valueOf(s, zero), 0u);
}

TEST(BlendDrawSetup, ValuesFollowTheParameters) {
  GsParams p;
  p.fix = 0x60;
  p.colclamp = "wrap";
  p.alpha_write = "keep";
  p.depth_format = "none";
  const BlendDrawSetup s = sampleSetup(p);
  EXPECT_EQ(valueOf(s, "ALPHA_1") >> 32, 0x60u);
  EXPECT_EQ(valueOf(s, "COLCLAMP"), 0u);
  EXPECT_EQ(valueOf(s, "FRAME_1") >> 32, 0xFF000000u);
  EXPECT_EQ(valueOf(s, "ZBUF_1"), std::uint64_t{1} << 32);  // no Z buffer: only ZMSK
  // Strip mode: a 32-row staging texture whose rows 0..31 land on the strip's rows.
  GsParams q;
  q.upload_mode = "strips";
  const BlendDrawSetup strip = sampleSetup(q, 64, 96);
  EXPECT_EQ((valueOf(strip, "TEX0_1") >> 30) & 0xF, 5u);  // TH = log2(32)
  EXPECT_EQ(valueOf(strip, "UV", 0), 0u);
  EXPECT_EQ(valueOf(strip, "UV", 1), (256u << 4) | ((32u << 4) << 16));
  EXPECT_EQ(valueOf(strip, "XYZ2", 0), (64u << 4) << 16);
  EXPECT_EQ(valueOf(strip, "XYZ2", 1), (256u << 4) | ((96u << 4) << 16));
}

TEST(BlendDrawSetup, TheSkyIsBlendedIntoTheSkyTextureFromItsOwnStagingArea) {
  const BlendDrawSetup s = sampleSkySetup();
  // VRAM: sky texture (256x256) at page 414, sky staging (128x64) at page 446 = block 14,272.
  EXPECT_EQ(valueOf(s, "FRAME_1"), 0x0004019Eu);            // FBP 414, FBW 4: the texture's width, not the stream's
  EXPECT_EQ(valueOf(s, "TEX0_1"), 0x000000059C00B7C0u);     // TBP0 14,272, TBW 2, TW 7, TH 6, TCC 1
  EXPECT_EQ(valueOf(s, "SCISSOR_1"), 0x003F0000007F0000u);  // the stream's 128x64 corner of the texture
  EXPECT_EQ(valueOf(s, "UV", 1), (128u << 4) | ((64u << 4) << 16));
  EXPECT_EQ(valueOf(s, "XYZ2", 1), (128u << 4) | ((64u << 4) << 16));
  // The rest is the lightmap's draw.
  const BlendDrawSetup lm = sampleSetup();
  for (const char* same : {"ZBUF_1", "TEST_1", "CLAMP_1", "ALPHA_1", "COLCLAMP", "PRIM", "RGBAQ"}) {
    EXPECT_EQ(valueOf(s, same), valueOf(lm, same)) << same;
  }
  // Strip mode: a 32-row sky staging area, as the lightmap's.
  GsParams q;
  q.upload_mode = "strips";
  const BlendDrawSetup strip = sampleSkySetup(q, 32, 64);
  EXPECT_EQ((valueOf(strip, "TEX0_1") >> 30) & 0xF, 5u);
  EXPECT_EQ(valueOf(strip, "XYZ2", 0), (32u << 4) << 16);
}

TEST(BlendDrawSetup, RefusesADrawTheLayoutCannotHold) {
  const GsParams p;
  const VramLayout noSky = planVram(p, 256, 256);  // planned without the sky stream's size
  EXPECT_THROW(blendDrawFor(noSky, p, BlendSurface::Sky, 128, 64, 0, 64), GsError);
  const VramLayout vram = planVram(p, 256, 256, SkyTexture{128, 64});
  EXPECT_NO_THROW(blendDrawFor(vram, p, BlendSurface::Sky, 128, 64, 0, 64));
  EXPECT_THROW(blendDrawFor(vram, p, BlendSurface::Sky, 256, 64, 0, 64), GsError);  // not the staging's width
  EXPECT_THROW(blendDrawFor(vram, p, BlendSurface::Sky, 128, 64, 0, 65), GsError);  // rows past the picture
  EXPECT_THROW(blendDrawFor(vram, p, BlendSurface::Lightmap, 512, 512, 0, 512), GsError);
  EXPECT_THROW(blendDrawFor(vram, p, BlendSurface::Lightmap, 256, 256, 16, 16), GsError);  // no rows
  GsParams q;
  q.upload_mode = "strips";
  const VramLayout strips = planVram(q, 256, 256);
  EXPECT_THROW(blendDrawFor(strips, q, BlendSurface::Lightmap, 256, 256, 0, 64), GsError);  // two strips
  EXPECT_NO_THROW(blendDrawFor(strips, q, BlendSurface::Lightmap, 256, 256, 224, 256));
}

// docs/porting.md lists the writes with their values for the samples: numbered rows
// "| n | `NAME` | fields | `0x...` |", in the order they are sent, for the lightmap's draw; then,
// for the sky's, the rows whose values differ from the lightmap's, with the same numbers.
TEST(BlendDrawSetup, PortingGuideListsTheSameWritesAndValues) {
  std::ifstream in(player::testing::sourceDir() + "/docs/porting.md");
  ASSERT_TRUE(in);
  struct Row {
    int n;
    std::string name;
    std::uint64_t value;
  };
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    int n = 0;
    char name[32] = {};
    unsigned long long value = 0;
    // NOLINTNEXTLINE(cert-err34-c): a row that does not match is not part of the table
    if (std::sscanf(line.c_str(), "| %d | `%31[A-Z0-9_]` | %*[^|]| `0x%llx` |", &n, name, &value) == 3) {
      rows.push_back(Row{n, name, value});
    }
  }
  const BlendDrawSetup s = sampleSetup();
  ASSERT_GE(rows.size(), s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(rows[i].n, static_cast<int>(i) + 1);
    EXPECT_EQ(rows[i].name, s[i].reg.name) << "row " << i + 1;
    EXPECT_EQ(rows[i].value, s[i].value) << "row " << i + 1 << " " << rows[i].name;
  }
  const BlendDrawSetup sky = sampleSkySetup();
  std::vector<int> differing;
  for (std::size_t i = 0; i < sky.size(); ++i) {
    if (sky[i].value != s[i].value) differing.push_back(static_cast<int>(i) + 1);
  }
  std::vector<int> listed;
  for (std::size_t k = s.size(); k < rows.size(); ++k) {
    const Row& r = rows[k];
    listed.push_back(r.n);
    ASSERT_TRUE(r.n >= 1 && r.n <= static_cast<int>(sky.size())) << r.n;
    const RegisterWrite& w = sky[static_cast<std::size_t>(r.n - 1)];
    EXPECT_EQ(r.name, w.reg.name) << "sky row " << r.n;
    EXPECT_EQ(r.value, w.value) << "sky row " << r.n << " " << r.name;
  }
  EXPECT_EQ(listed, differing) << "the sky's table lists exactly the rows that differ from the lightmap's";
}

}  // namespace
}  // namespace vbim::gs
