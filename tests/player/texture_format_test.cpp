// gs.texture_format = ct16, the 16-bit lightmap path (gs/blend16.hpp, docs/porting.md): the model's
// output differs from the 32-bit path's (5-bit channels, two dithers), every stored texel is one a
// PSMCT16 texture can hold, and the upload moves half the bytes in as many transfers. The default
// (ct32) keeps its bytes: the golden hashes of tests/player/golden are made with it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "player/platform_config.hpp"
#include "player/scenario.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::player {
namespace {

struct Played {
  std::vector<std::uint64_t> hashes;
  gs::PresenterCounters lightmap;
  gs::PresenterCounters sky;
  Rgba8Image lastLightmap;
  int lightmapPages = 0;
};

Played play(const std::string& format) {
  PlatformConfig c;
  c.gs.texture_format = format;
  auto run =
      Scenario::bareFile(testing::samplePath("day_weather.vbim")).config(c).seed(3).trace(false).start(fromMs(20'000));
  run->runToEnd();
  Pipeline& p = run->player().pipeline();
  return Played{run->hashes(), p.lightmap().counters(), p.sky()->counters(), p.lightmap().lightmap(),
                p.lightmap().vram().region("lightmap").pages};
}

TEST(TextureFormat, SixteenBitPathShowsTheSameFramesWithItsOwnPixels) {
  const Played ct32 = play("ct32");
  const Played ct16 = play("ct16");
  ASSERT_GT(ct16.lightmap.framesShown, 3);
  EXPECT_EQ(ct16.lightmap.framesShown, ct32.lightmap.framesShown);
  EXPECT_EQ(ct16.sky.framesShown, ct32.sky.framesShown);
  ASSERT_EQ(ct16.hashes.size(), ct32.hashes.size());
  EXPECT_NE(ct16.hashes.back(), ct32.hashes.back());
  // Every texel is a PSMCT16 one as the GS expands it: 5-bit colours << 3, alpha 0 or 0x80.
  const std::vector<std::uint8_t>& px = ct16.lastLightmap.pixels;
  for (std::size_t i = 0; i < px.size(); ++i) {
    if (i % 4 == 3) {
      ASSERT_TRUE(px[i] == 0 || px[i] == 0x80) << "byte " << i;
    } else {
      ASSERT_EQ(px[i] & 7, 0) << "byte " << i;
    }
  }
  // The 32-bit lightmap has colours the 16-bit one cannot hold.
  bool fine = false;
  for (std::size_t i = 0; i < ct32.lastLightmap.pixels.size(); i += 4) fine = fine || (ct32.lastLightmap.pixels[i] & 7);
  EXPECT_TRUE(fine);
  EXPECT_EQ(ct16.lightmapPages * 2, ct32.lightmapPages);  // 64x64 pages instead of 64x32
}

TEST(TextureFormat, SixteenBitUploadsMoveHalfTheBytes) {
  const Played ct32 = play("ct32");
  const Played ct16 = play("ct16");
  ASSERT_GT(ct32.lightmap.uploadBytes, 0);
  EXPECT_EQ(ct16.lightmap.uploadBytes * 2, ct32.lightmap.uploadBytes);
  EXPECT_EQ(ct16.sky.uploadBytes * 2, ct32.sky.uploadBytes);
  EXPECT_EQ(ct16.lightmap.uploadTransfers, ct32.lightmap.uploadTransfers);
  EXPECT_EQ(ct16.lightmap.uploadSetupQwords, ct32.lightmap.uploadSetupQwords);
  EXPECT_LT(ct16.lightmap.gsBusy, ct32.lightmap.gsBusy);
}

}  // namespace
}  // namespace vbim::player
