// `vbim config --check` runs every check `vbim play` runs (issue #15): a config play refuses is
// refused by config --check with the same message, naming `file:line: key`; with --stream the VRAM
// layout is checked against that stream's frame sizes, without it against the smallest lightmap.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::runCommand;
using vbim::testing::writeTextFile;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

class ConfigCheckCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vbim_config_check_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string config(const std::string& text) const {
    const fs::path p = dir_ / "platform.toml";
    EXPECT_TRUE(writeTextFile(p, text));
    return p.string();
  }
  static vbim::testing::CommandResult vbim(const std::string& args) {
    return runCommand(std::string(VBIM_BINARY) + " " + args);
  }
  // The message after "vbim CMD: ", and checks that the command refused with exit 2.
  static std::string refusal(const vbim::testing::CommandResult& r, const std::string& command) {
    EXPECT_EQ(r.status, 2) << r.output;
    const std::string prefix = "vbim " + command + ": ";
    EXPECT_EQ(r.output.rfind(prefix, 0), 0u) << r.output;
    return r.output.rfind(prefix, 0) == 0 ? r.output.substr(prefix.size()) : r.output;
  }
  std::string play(const std::string& cfg) const {
    return refusal(
        vbim("play " + kSample + " --config " + cfg + " --duration 1s --no-trace --out " + (dir_ / "run").string()),
        "play");
  }

  fs::path dir_;
};

TEST_F(ConfigCheckCli, StripRowsNotAPageHighAreRefusedByBothWithTheSameMessage) {
  const std::string cfg = config("[gs]\nfix = 64\nstrip_rows = 33\n");
  const std::string fromPlay = play(cfg);
  EXPECT_EQ(fromPlay.rfind(cfg + ":3: key 'gs.strip_rows': strip rows 33 must be a positive multiple of 32", 0), 0u)
      << fromPlay;
  EXPECT_EQ(refusal(vbim("config --check " + cfg), "config"), fromPlay);
  EXPECT_EQ(refusal(vbim("config --check " + cfg + " --stream " + kSample), "config"), fromPlay);
  EXPECT_FALSE(fs::exists(dir_ / "run"));
}

// A 512x512 sky leaves room for a small lightmap but not for the sample's 256x256 one.
TEST_F(ConfigCheckCli, AVramOverflowForAStreamIsRefusedByBothWithTheSameMessage) {
  const std::string cfg = config("gs.sky_width = 512\ngs.sky_height = 512\n");
  const std::string fromPlay = play(cfg);
  EXPECT_EQ(fromPlay.rfind(cfg + ":1: key 'gs.sky_width': VRAM layout does not fit", 0), 0u) << fromPlay;
  EXPECT_EQ(refusal(vbim("config --check " + cfg + " --stream " + kSample), "config"), fromPlay);
  // Without a stream the config can still work for a smaller lightmap: valid.
  const auto alone = vbim("config --check " + cfg);
  EXPECT_EQ(alone.status, 0) << alone.output;
  EXPECT_NE(alone.output.find(cfg + ": valid"), std::string::npos) << alone.output;
}

// The sample's 128x64 sky does not fit a 64-row sky texture: play and config --check --stream refuse
// it alike, naming the key; without a stream there is no sky to compare.
TEST_F(ConfigCheckCli, ASkyTextureSmallerThanTheSkyStreamIsRefusedByBoth) {
  const std::string cfg = config("gs.sky_height = 32\n");
  const std::string fromPlay = play(cfg);
  EXPECT_EQ(fromPlay.rfind(cfg + ":1: key 'gs.sky_height': the sky stream is 128x64 but VRAM keeps a 256x32 sky", 0),
            0u)
      << fromPlay;
  EXPECT_EQ(refusal(vbim("config --check " + cfg + " --stream " + kSample), "config"), fromPlay);
  EXPECT_EQ(vbim("config --check " + cfg).status, 0);
}

// The largest frame the keys allow fills VRAM on its own: no stream can play, and both say so.
TEST_F(ConfigCheckCli, TheLargestFrameIsRefusedWithOrWithoutAStream) {
  const std::string cfg = config("[gs]\nframe_width = 2048\nframe_height = 2048\n");
  const std::string fromPlay = play(cfg);
  EXPECT_EQ(fromPlay.rfind(cfg + ":2: key 'gs.frame_width': VRAM layout does not fit", 0), 0u) << fromPlay;
  EXPECT_NE(fromPlay.find("leave no room for a lightmap"), std::string::npos) << fromPlay;
  EXPECT_EQ(refusal(vbim("config --check " + cfg + " --stream " + kSample), "config"), fromPlay);
  const std::string alone = refusal(vbim("config --check " + cfg), "config");
  EXPECT_EQ(alone.rfind(cfg + ":2: key 'gs.frame_width': VRAM layout does not fit", 0), 0u) << alone;
}

TEST_F(ConfigCheckCli, AConfigPlayAcceptsIsValid) {
  const std::string cfg = config("[gs]\nupload_mode = \"strips\"\nstrip_rows = 64\n");
  const auto r = vbim("config --check " + cfg + " --stream " + kSample);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(cfg + " with " + kSample + ": valid"), std::string::npos) << r.output;
  const auto p =
      vbim("play " + kSample + " --config " + cfg + " --duration 1s --no-trace --out " + (dir_ / "run").string());
  EXPECT_EQ(p.status, 0) << p.output;
}

// --gs-setup prints the plan play uses and both presenters' draws (the values themselves are checked
// in tests/gs/draw_setup_test.cpp); a config play refuses is refused the same way.
TEST_F(ConfigCheckCli, GsSetupListsTheVramPlanAndBothDraws) {
  const std::string cfg = config("[gs]\nupload_mode = \"strips\"\n");
  const auto r = vbim("config --gs-setup --check " + cfg + " --stream " + kSample);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* part : {"page 350: lightmap 256x256", "page 382: staging 256x32", "sky staging 128x32",
                           "## lightmap 256x256: lightmap at page 350, blended from staging at page 382",
                           "Draw 1 of 8 per vsync", "## sky 128x64: sky at page 386", "Draw 1 of 2 per vsync",
                           "| 2 | `FRAME_1` | 0x4C | `0x4015E` |", "| 19 | `XYZ2` | 0x05 | `0x2000800` |"}) {
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
  }
  EXPECT_EQ(r.output.find("# vbim platform config"), std::string::npos) << "the setup replaces the config";
  const std::string refused = config("gs.sky_height = 32\n");
  EXPECT_EQ(refusal(vbim("config --gs-setup --check " + refused + " --stream " + kSample), "config"), play(refused));
  EXPECT_NE(vbim("config --gs-setup").output.find("--gs-setup requires --stream"), std::string::npos);
}

TEST_F(ConfigCheckCli, AStreamThatIsNotOneIsNamed) {
  const std::string cfg = config("gs.fix = 64\n");
  const fs::path junk = dir_ / "junk.vbim";
  ASSERT_TRUE(writeTextFile(junk, std::string(4096, 'x')));
  const std::string r = refusal(vbim("config --check " + cfg + " --stream " + junk.string()), "config");
  EXPECT_NE(r.find(junk.string()), std::string::npos) << r;
}

}  // namespace
