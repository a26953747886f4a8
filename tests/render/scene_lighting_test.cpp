#include <gtest/gtest.h>

#include <cmath>

#include "render/scene_lighting.hpp"
#include "render_test_scene.hpp"

namespace vbim::render {
namespace {

// The sun visibility read back from the streamed lightmap matches the generator's own shadow mask
// where the direct term is measurable, and the stream's exposure (-1 EV) is recovered.
TEST(SceneLighting, RecoversTheGeneratorsShadowsAndExposure) {
  for (int frame : {8, 12, 17}) {
    const test::StreamedFrame f = test::streamedFrame(frame);
    SceneLighting lighting(test::smallTerrain(), test::smallDay());
    const FrameLight light = lighting.evaluate(frame, f.lightmap, &f.sky);
    EXPECT_NEAR(light.streamScale, 0.5, 0.06) << "frame " << frame;
    double err = 0;
    int n = 0, shadowed = 0;
    for (std::size_t i = 0; i < light.sunVisibility.size(); ++i) {
      if (light.sunVisibility[i] <= 0 && f.shadowMask.pixels[i] > 0.5f) continue;  // slope facing away: not measurable
      err += std::fabs(light.sunVisibility[i] - f.shadowMask.pixels[i]);
      ++n;
      shadowed += f.shadowMask.pixels[i] < 0.5f;
    }
    ASSERT_GT(n, 1000) << "frame " << frame;
    EXPECT_LT(err / n, 0.08) << "frame " << frame << ": mean |O - mask| over " << n << " texels";
    if (frame == 17) {
      EXPECT_GT(shadowed, 20) << "an evening frame should have shadows to compare";
    }
    EXPECT_GT(light.sunDirection[1], 0.0f) << "the sun is up at frame " << frame;
    EXPECT_GT(light.skyIrradiance[2], light.skyIrradiance[0]) << "a blue sky";
  }
}

TEST(SceneLighting, SeqWrapsAtTheLoopFrame) {
  SceneLighting lighting(test::smallTerrain(), test::smallDay(), 4);
  EXPECT_EQ(lighting.frameOfSeq(0), 0);
  EXPECT_EQ(lighting.frameOfSeq(23), 23);
  EXPECT_EQ(lighting.frameOfSeq(24), 4);
  EXPECT_EQ(lighting.frameOfSeq(24 + 20), 4);
  EXPECT_EQ(lighting.frameOfSeq(-1), 0);
}

TEST(SceneLighting, SrgbDecode) {
  EXPECT_EQ(srgbToLinear(0), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(255), 1.0f);
  EXPECT_NEAR(srgbToLinear(188), 0.5, 0.003);
}

}  // namespace
}  // namespace vbim::render
