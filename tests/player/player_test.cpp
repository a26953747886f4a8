#include <gtest/gtest.h>

#include "config/platform_config_toml.hpp"
#include "gs/error.hpp"
#include "player/scenario.hpp"
#include "streams/descriptor_probe.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::player {
namespace {

using testing::samplePath;

TEST(Player, PlaysTheClearDayWithoutFaults) {
  auto run = Scenario::bareFile(samplePath("day_clear.vbim")).seed(1).start(fromMs(6'000));
  run->runToEnd();
  const auto& c = run->counters();
  EXPECT_EQ(run->rows().size(), 360u);  // 6 s at 59.94 Hz
  EXPECT_GE(c.framesShown, 6);          // frames 0..5 (frame k due at 0.5 s + k s)
  EXPECT_EQ(c.framesLate, 0);
  EXPECT_EQ(run->lastRow().lag, 0);
  EXPECT_FALSE(run->player().hasReference());
  EXPECT_EQ(run->player().pipeline().demux().counters().framesLost, 0);
  ASSERT_NE(run->sky(), nullptr);
  EXPECT_EQ(run->player().pipeline().sky()->counters().framesShown, c.framesShown);  // sky in step
}

// One console, one VRAM plan: the sky presenter plans none of its own; it blends into the plan's sky
// texture from the sky's staging area, which the lightmap presenter's plan holds.
TEST(Player, TheSkyIsBlendedInTheLightmapPresentersVramPlan) {
  auto run = Scenario::bareFile(samplePath("day_clear.vbim")).seed(1).trace(false).start(fromMs(1'000));
  Pipeline& p = run->player().pipeline();
  ASSERT_NE(p.sky(), nullptr);
  EXPECT_EQ(p.sky()->vram().describe(), p.lightmap().vram().describe());
  const gs::BlendDraw sky = p.sky()->blendDraw(0, 64);
  EXPECT_EQ(sky.frame.name, "sky");
  EXPECT_EQ(sky.texture.name, "sky staging");
  EXPECT_EQ(sky.width, 128);
  EXPECT_EQ(sky.height, 64);
  const gs::BlendDraw lightmap = p.lightmap().blendDraw(0, 256);
  EXPECT_EQ(lightmap.frame.name, "lightmap");
  EXPECT_EQ(lightmap.texture.name, "staging");
  EXPECT_THROW(p.sky()->blendDraw(0, 65), gs::GsError);  // past the sky stream's 64 rows
}

TEST(Player, WrapsAtTheLoopPointBySeekingTheRing) {
  auto run = Scenario::bareFile(samplePath("day_clear.vbim")).seed(2).trace(false).start(fromMs(52'000));
  run->runToEnd();
  const auto& c = run->counters();
  EXPECT_GE(c.loopWraps, 1);
  EXPECT_GE(run->player().pipeline().demux().counters().loopSeeks, 1);
  EXPECT_EQ(c.framesLate, 0);
  EXPECT_EQ(run->player().pipeline().demux().counters().framesLost, 0);
  // After the wrap the lightmap blends toward frame 0 again: target seq 48 shows stream frame 0.
  EXPECT_GE(run->lastRow().lightmap.targetSeq, 50);
}

// In day_weather the small sky stream runs ahead in the file: the overcast variant's sky pictures
// start (sector 26) long before the clear variant's last lightmap picture (sector 48). The demux
// once took the variant's first sector for the end of every stream's pictures, gave up on lightmap
// frames 6..11 of every lap as lost and showed 18 of 30 frames in a clean minute.
TEST(Player, AVariantEndsPerStreamWhenTheSkyRunsAhead) {
  auto run = Scenario::bareFile(samplePath("day_weather.vbim")).seed(4).trace(false).start(fromMs(60'000));
  run->runToEnd();
  const auto& c = run->counters();
  EXPECT_EQ(c.framesShown, 30);  // one frame every 2 s, two laps of 12 and more
  EXPECT_EQ(c.framesDropped, 0);
  EXPECT_EQ(c.framesLate, 0);
  EXPECT_EQ(c.behindVsyncs, 0);
  EXPECT_EQ(c.loopWraps, 2);
  EXPECT_EQ(run->player().pipeline().demux().counters().framesLost, 0);
  EXPECT_EQ(run->player().pipeline().sky()->counters().framesShown, 30);
}

TEST(Player, LongStallThenSmoothCatchUp) {
  auto run = Scenario::bareFile(samplePath("day_clear.vbim"))
                 .seed(3)
                 .config(PlatformConfig{})
                 .config(config::loadPlatformToml(
                     "ring.bufmax_sectors = 8\nring.bankmax = 4\nee.read_sectors = 1\nee.compressed_frames = 1\n",
                     "<scenario config>"))
                 .stall(fromMs(1'000), fromMs(30'000))
                 .start(fromMs(36'000));
  run->runToEnd();
  EXPECT_TRUE(run->player().hasReference());
  const auto& c = run->counters();
  EXPECT_GT(c.framesLate, 0);
  EXPECT_GT(c.behindVsyncs, 0);
  EXPECT_GT(run->totals().lag.value, 8);
  EXPECT_GT(c.framesCaughtUp, 0);  // late frames blended toward, not snapped (blend-through)
  // Converged back onto the fault-free run, to within the blend's floor band (gs/README.md).
  EXPECT_LE(run->lastRow().lag, 1);
  if (HasFailure()) std::cerr << run->statsJson();
}

TEST(Player, ReadErrorIsRetriedAndPlayContinues) {
  auto run = Scenario::bareFile(samplePath("day_clear.vbim")).seed(4).readError(40, 600).start(fromMs(12'000));
  run->runToEnd();
  EXPECT_GT(run->player().pipeline().drive().stats().retries, 0);
  EXPECT_GE(run->counters().framesShown, 10);
}

TEST(Player, BranchesToTheWeatherVariantAtTheSameTimeOfDay) {
  auto run = Scenario::bareFile(samplePath("day_weather.vbim")).seed(5).branch(fromMs(9'000), 1).start(fromMs(16'000));
  run->runToEnd();
  const auto& c = run->counters();
  EXPECT_EQ(c.branches, 1);
  EXPECT_EQ(run->lastRow().lightmap.variant, 1);
  ASSERT_TRUE(run->lastRow().sky.has_value());
  EXPECT_EQ(run->lastRow().sky->variant, 1);
  EXPECT_GE(run->player().pipeline().demux().counters().seeks, 1);
}

TEST(Player, RejectsAFileThatIsNotAVbimStream) {
  const std::string bad = ::testing::TempDir() + "/not_vbim.bin";
  {
    std::FILE* f = std::fopen(bad.c_str(), "wb");
    std::vector<char> zeros(4096, 0x42);
    std::fwrite(zeros.data(), 1, zeros.size(), f);
    std::fclose(f);
  }
  try {
    Scenario::bareFile(bad).start(fromMs(1'000));
    FAIL() << "expected a StreamProbeError";
  } catch (const streams::StreamProbeError& e) {
    EXPECT_NE(std::string(e.what()).find("not a VBIM stream"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sector 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vbim::player
