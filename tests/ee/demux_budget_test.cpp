// The EE demux's store is bounded however the file is muxed (issue #7 item 9): a stream whose sky
// drifts behind its lightmap in the file (authored without the container-time stretch) makes the
// demux store lightmap pictures beyond the buffer depth; past ee.compressed_budget_kib it drops
// them (their frames lost, as with damage) instead of growing, and playback goes on.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "config/platform_config_toml.hpp"
#include "player/scenario.hpp"
#include "streams/authoring/bench_stream.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::player {
namespace {

namespace fs = std::filesystem;

class DemuxBudget : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    path_ = fs::temp_directory_path() / ("vbim_drift_" + std::to_string(::getpid()) + ".vbim");
    const auto bytes = streams::authorBenchStream(24, streams::BenchContent::Noise, 1, /*stretchContainerTime=*/false);
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    // The premise: the pictures of one frame end far apart in the file.
    const streams::StreamScan scan = streams::scanStream(bytes);
    const streams::Descriptor& d = *scan.descriptor;
    drift_ = 0;
    for (std::uint32_t f = 0; f < d.totalFrames(); ++f)
      drift_ = std::max<std::int64_t>(drift_, std::abs(static_cast<std::int64_t>(d.index[0][f].sector) -
                                                       static_cast<std::int64_t>(d.index[1][f].sector)));
  }
  static void TearDownTestSuite() { fs::remove(path_); }

  static std::unique_ptr<player::Run> play(const std::string& extraToml) {
    auto run = Scenario::bareFile(path_.string())
                   .config(config::loadPlatformToml("gs.upload_mode = \"strips\"\ngs.sky_height = 128\n" + extraToml,
                                                    "<scenario config>"))
                   .seed(3)
                   .trace(false)
                   .start(fromMs(48'000));
    run->runToEnd();
    return run;
  }
  static const ee::DemuxCounters& demux(player::Run& run) { return run.player().pipeline().demux().counters(); }

  static inline fs::path path_;
  static inline std::int64_t drift_ = 0;
};

TEST_F(DemuxBudget, TheDriftingStreamDrifts) {
  EXPECT_GT(drift_, 300) << "the test stream should put a frame's pictures hundreds of sectors apart";
}

TEST_F(DemuxBudget, WithinTheDefaultBudgetEveryFrameArrives) {
  auto run = play("");
  const ee::DemuxCounters& c = demux(*run);
  EXPECT_GT(c.overDepth, 0) << "the drift should make the demux store beyond the buffer depth";
  EXPECT_EQ(c.overBudget, 0);
  EXPECT_EQ(c.framesLost, 0);
}

TEST_F(DemuxBudget, PastASmallBudgetPicturesAreDroppedAndPlayGoesOn) {
  auto run = play("ee.compressed_budget_kib = 256\n");
  const ee::DemuxCounters& c = demux(*run);
  EXPECT_GT(c.overBudget, 0);
  EXPECT_GE(c.framesLost, c.overBudget);
  // Played to the end: every vsync of the 48 s recorded (n = 0 .. floor(48 s x 60000/1001)),
  // frames still shown.
  EXPECT_EQ(run->rows().size(), 2878u);
  EXPECT_GT(run->lastRow().at, fromMs(47'900));
  EXPECT_GT(run->counters().framesShown, 5);
  EXPECT_NE(run->statsJson().find("\"pictures_over_budget\": " + std::to_string(c.overBudget)), std::string::npos);
}

}  // namespace
}  // namespace vbim::player
