#include "gs/vram.hpp"

#include <gtest/gtest.h>

#include "gs/error.hpp"
#include "gs/presenter.hpp"

namespace vbim::gs {
namespace {

std::string refusal(const GsParams& p, int w, int h) {
  try {
    planVram(p, w, h);
  } catch (const GsError& e) {
    return e.what();
  }
  return {};
}

TEST(Vram, PageShapes) {
  EXPECT_EQ(pagesFor(Psm::Ct32, 640, 448), 140);  // 10 x 14
  EXPECT_EQ(pagesFor(Psm::Z16, 640, 448), 70);    // 10 x 7
  EXPECT_EQ(pagesFor(Psm::Ct32, 256, 256), 32);
  EXPECT_EQ(pagesFor(Psm::Ct32, 1, 1), 1);
  EXPECT_EQ(pagesFor(Psm::Ct32, 65, 33), 4);
  EXPECT_EQ(kVramPages * kPageBytes, 4 * 1024 * 1024);
}

TEST(Vram, DefaultLayoutFitsAndIsPageAligned) {
  const GsParams p;
  const VramLayout v = planVram(p, 256, 256);
  // 2 x 140 (frames) + 70 (Z16) + 32 (lightmap) + 32 (staging) + 32 (sky) = 446 pages.
  EXPECT_EQ(v.pagesUsed(), 446);
  EXPECT_EQ(v.pagesFree(), 66);
  EXPECT_EQ(v.region("frame0").firstPage, 0);
  EXPECT_EQ(v.region("frame1").firstPage, 140);
  EXPECT_EQ(v.region("depth").firstPage, 280);
  EXPECT_EQ(v.region("lightmap").firstPage, 350);
  EXPECT_EQ(v.region("lightmap").basePointer(), 350 * 32);
  EXPECT_EQ(v.region("staging").pages, 32);
  EXPECT_TRUE(v.has("sky"));
  EXPECT_NE(v.describe().find("used 446 of 512 pages"), std::string::npos) << v.describe();
}

// The sky is blended in place like the lightmap, through a staging area of its own: one budget for
// the console (before, each presenter planned alone and the sky's staging was in no plan).
TEST(Vram, TheSkyStreamsStagingAreaIsInTheSameBudget) {
  GsParams p;
  const VramLayout v = planVram(p, 256, 256, SkyTexture{128, 64});  // the samples
  // 446 as above + 4 (128x64: 2 x 2 pages).
  EXPECT_EQ(v.pagesUsed(), 450);
  EXPECT_EQ(v.region("lightmap").firstPage, 350);  // nothing before the sky moves
  EXPECT_EQ(v.region("sky").firstPage, 414);
  EXPECT_EQ(v.region("sky staging").firstPage, 446);
  EXPECT_EQ(v.region("sky staging").pages, 4);
  // Strips: one strip of the sky too. The 512x512 speed case: 280 + 70 + 128 + 8 + 16 + 4 pages.
  p.upload_mode = "strips";
  p.sky_height = 128;
  const VramLayout big = planVram(p, 512, 512, SkyTexture{256, 128});
  EXPECT_EQ(big.region("sky staging").height, 32);
  EXPECT_EQ(big.pagesUsed(), 506);
}

TEST(Vram, ASkyStreamLargerThanItsTextureIsRefused) {
  GsParams p;
  p.sky_height = 32;
  try {
    planVram(p, 256, 256, SkyTexture{128, 64});
    FAIL() << "expected GsError";
  } catch (const GsError& e) {
    EXPECT_EQ(std::string(e.what()),
              "the sky stream is 128x64 but VRAM keeps a 256x32 sky texture (gs.sky_width x gs.sky_height): set "
              "them to at least the stream's size");
    EXPECT_EQ(e.keys(), (std::vector<std::string>{"gs.sky_width", "gs.sky_height"}));
  }
}

TEST(Vram, OversizedLayoutIsRefusedWithTheSizes) {
  GsParams p;
  const std::string msg = refusal(p, 1024, 1024);
  ASSERT_FALSE(msg.empty());
  // 280 + 70 + 512 + 512 + 32 = 1406 pages.
  EXPECT_NE(msg.find("needs 1406 pages"), std::string::npos) << msg;
  EXPECT_NE(msg.find("512 pages of 8 KiB"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lightmap 1024x1024 PSMCT32 = 512 pages"), std::string::npos) << msg;
  EXPECT_NE(msg.find("staging 1024x1024 PSMCT32 = 512 pages"), std::string::npos) << msg;
  EXPECT_NE(msg.find("frame0 640x448 PSMCT32 = 140 pages"), std::string::npos) << msg;
  EXPECT_NE(msg.find("depth 640x448 PSMZ16 = 70 pages"), std::string::npos) << msg;
}

TEST(Vram, StripModeMakesALayoutFit) {
  GsParams p;
  // 512x320 lightmap: full staging needs 280 + 70 + 80 + 80 + 32 = 542 pages.
  EXPECT_NE(refusal(p, 512, 320).find("needs 542 pages"), std::string::npos);
  p.upload_mode = "strips";
  const VramLayout v = planVram(p, 512, 320);
  EXPECT_EQ(v.region("staging").pages, 8);  // 512x32: one strip
  EXPECT_EQ(v.pagesUsed(), 470);
}

TEST(Vram, TextureAndCoordinateLimits) {
  GsParams p;
  p.frame_buffers = 0;
  p.depth_format = "none";
  EXPECT_NE(refusal(p, 2048, 16).find("1..1024"), std::string::npos);
  EXPECT_NE(refusal(p, 0, 16).find("1..1024"), std::string::npos);
  EXPECT_THROW(VramLayout::place({{"x", Psm::Ct32, 4096, 1}}), GsError);
  EXPECT_THROW(psmByName("ct8"), GsError);
}

}  // namespace
}  // namespace vbim::gs
