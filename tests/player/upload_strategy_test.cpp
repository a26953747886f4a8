// gs.upload_strategy: how the IPU's macroblock-order output reaches the staging texture
// (docs/timing/gs.md, "Upload strategy"). The three strategies move the same pixels, so the
// lightmap hashes are the same; they cost different simulated time, which these tests check to the
// tick against the formulas of docs/timing/gs.md and docs/timing/ee.md.
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
  ee::DecodeCounters decode;
};

Played play(const std::string& strategy, const std::string& uploadMode = "full",
            const std::string& textureFormat = "ct32") {
  PlatformConfig c;
  c.gs.upload_strategy = strategy;
  c.gs.texture_format = textureFormat;
  c.gs.upload_mode = uploadMode;
  if (uploadMode == "strips") c.gs.sky_height = 128;
  auto run =
      Scenario::bareFile(testing::samplePath("day_weather.vbim")).config(c).seed(3).trace(false).start(fromMs(20'000));
  run->runToEnd();
  Pipeline& p = run->player().pipeline();
  return Played{run->hashes(), p.lightmap().counters(), p.sky()->counters(), p.decode()};
}

// The samples: a 256x256 lightmap (256 macroblocks) and a 128x64 sky (32 macroblocks).
constexpr std::int64_t kLightmapMacroblocks = 256;
constexpr std::int64_t kSkyMacroblocks = 32;

TEST(UploadStrategy, EveryStrategyShowsTheSamePixels) {
  const Played mb = play("macroblocks");
  const Played reorder = play("ee-reorder");
  const Played raster = play("raster");
  ASSERT_GT(mb.lightmap.framesShown, 3);
  EXPECT_EQ(mb.hashes, raster.hashes);
  EXPECT_EQ(reorder.hashes, raster.hashes);
  EXPECT_EQ(mb.lightmap.framesShown, raster.lightmap.framesShown);
  EXPECT_EQ(reorder.lightmap.framesShown, raster.lightmap.framesShown);
}

TEST(UploadStrategy, MacroblockTransfersCostTheirSetupOnTheGif) {
  const Played mb = play("macroblocks");
  const Played raster = play("raster");
  const std::int64_t uploads = raster.lightmap.uploadTransfers;
  ASSERT_GT(uploads, 0);
  EXPECT_EQ(uploads * 262'144, raster.lightmap.uploadBytes);  // one transfer per new frame
  EXPECT_EQ(mb.lightmap.uploadBytes, raster.lightmap.uploadBytes);
  EXPECT_EQ(mb.lightmap.uploadTransfers, uploads * kLightmapMacroblocks);
  EXPECT_EQ(mb.sky.uploadTransfers, raster.sky.uploadTransfers * kSkyMacroblocks);
  // 6 qwords for the first macroblock, 4 for each further one: 1,026 per 256x256 frame, against 6.
  EXPECT_EQ(mb.lightmap.uploadSetupQwords, uploads * 1'026);
  EXPECT_EQ(raster.lightmap.uploadSetupQwords, uploads * 6);
  // (1,026 - 6) qwords x 16 bytes / 8 bytes per tick = 2,040 more GIF ticks per uploaded frame.
  EXPECT_EQ(mb.lightmap.gsBusy - raster.lightmap.gsBusy, uploads * 2'040);
  // No EE work for either.
  EXPECT_EQ(mb.decode.reorderedQwords, 0);
  EXPECT_EQ(raster.decode.reorderBusy, 0);
}

TEST(UploadStrategy, EeReorderCostsTheEeAndNotTheGif) {
  const Played reorder = play("ee-reorder");
  const Played raster = play("raster");
  const std::int64_t lmPictures = reorder.decode.picturesPerStream[0];
  const std::int64_t skyPictures = reorder.decode.picturesPerStream[1];
  ASSERT_GT(lmPictures, 3);
  ASSERT_GT(skyPictures, 3);
  // 64 qwords per macroblock; 8 EE cycles per qword = 4 ticks.
  EXPECT_EQ(reorder.decode.reorderedQwords, (lmPictures * kLightmapMacroblocks + skyPictures * kSkyMacroblocks) * 64);
  EXPECT_EQ(reorder.decode.reorderBusy, reorder.decode.reorderedQwords * 4);
  // One raster transfer per frame, as without the reorder.
  EXPECT_EQ(reorder.lightmap.uploadTransfers, raster.lightmap.uploadTransfers);
  EXPECT_EQ(reorder.lightmap.gsBusy, raster.lightmap.gsBusy);
}

// The 16-bit path (issue #30): the IPU writes RGB16 (OFM = 1), 32 qwords a macroblock, so the EE
// reorders half the qwords of RGB32 and the upload moves 2 bytes a pixel.
TEST(UploadStrategy, Ct16ReordersAndUploadsTheIpusRgb16) {
  const Played reorder = play("ee-reorder", "full", "ct16");
  const std::int64_t lmPictures = reorder.decode.picturesPerStream[0];
  const std::int64_t skyPictures = reorder.decode.picturesPerStream[1];
  ASSERT_GT(lmPictures, 3);
  EXPECT_EQ(reorder.decode.reorderedQwords, (lmPictures * kLightmapMacroblocks + skyPictures * kSkyMacroblocks) * 32);
  EXPECT_EQ(reorder.decode.reorderBusy, reorder.decode.reorderedQwords * 4);
  EXPECT_EQ(reorder.lightmap.uploadBytes, reorder.lightmap.uploadTransfers * 256 * 256 * 2);
  const Played raster = play("raster", "full", "ct16");
  EXPECT_EQ(reorder.hashes, raster.hashes);
}

TEST(UploadStrategy, StripsUploadTheirOwnMacroblockRows) {
  const Played mb = play("macroblocks", "strips");
  const Played raster = play("raster", "strips");
  // Every vsync with a frame streams 8 strips of 256x32; each strip is 2 rows of 16 macroblocks.
  ASSERT_GT(raster.lightmap.uploadTransfers, 300 * 8);
  EXPECT_EQ(raster.lightmap.uploadTransfers % 8, 0);
  EXPECT_EQ(mb.lightmap.uploadTransfers, raster.lightmap.uploadTransfers * 32);
  EXPECT_EQ(mb.hashes, raster.hashes);
}

}  // namespace
}  // namespace vbim::player
