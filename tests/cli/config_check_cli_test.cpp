// `vbim config --check` runs every check `vbim play` runs (issue #15): a config play refuses is
// refused by config --check with the same message, naming `file:line: key`; with --stream the VRAM
// layout is checked against that stream's frame sizes, without it against the smallest lightmap.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::runCommand;
using vbim::testing::writeTextFile;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

class ConfigCheckCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = vbim::testing::testScratchDir("config_check_cli"); }
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

// --format gif prints each qword's bytes, --format c the same qwords as C arrays: the two agree, the
// packets are the ones tests/gs/gif_packets_test.cpp checks field by field, and the default stays the
// Markdown table.
TEST_F(ConfigCheckCli, GsSetupPacketsAsBytesAndAsCArraysAgree) {
  const auto gif = vbim("config --gs-setup --format gif --stream " + kSample);
  const auto c = vbim("config --gs-setup --format c --stream " + kSample);
  ASSERT_EQ(gif.status, 0) << gif.output;
  ASSERT_EQ(c.status, 0) << c.output;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> fromGif, fromC;
  std::istringstream g(gif.output);
  for (std::string line; std::getline(g, line);) {
    unsigned offset = 0;
    unsigned b[16];
    if (std::sscanf(line.c_str(), "%4x  %2x %2x %2x %2x %2x %2x %2x %2x  %2x %2x %2x %2x %2x %2x %2x %2x", &offset,
                    &b[0], &b[1], &b[2], &b[3], &b[4], &b[5], &b[6], &b[7], &b[8], &b[9], &b[10], &b[11], &b[12],
                    &b[13], &b[14], &b[15]) != 17) {
      continue;
    }
    std::uint64_t lo = 0, hi = 0;
    for (int i = 7; i >= 0; --i) {
      lo = lo << 8 | b[i];
      hi = hi << 8 | b[8 + i];
    }
    fromGif.emplace_back(lo, hi);
  }
  std::istringstream cs(c.output);
  for (std::string line; std::getline(cs, line);) {
    unsigned long long lo = 0, hi = 0;
    if (std::sscanf(line.c_str(), " {0x%llxULL, 0x%llxULL},", &lo, &hi) == 2) fromC.emplace_back(lo, hi);
  }
  // Lightmap: macroblock upload 6 + next 4 + draw 20 + copy 20; sky the same.
  EXPECT_EQ(fromGif.size(), 100u) << gif.output;
  EXPECT_EQ(fromGif, fromC) << c.output;
  for (const char* part : {"## lightmap_upload: 6 qwords + 64 qwords of pixels", "## sky_draw_copy: 20 qwords",
                           "; ALPHA_1 = 0x8000000064", "sends them again after the"}) {
    EXPECT_NE(gif.output.find(part), std::string::npos) << part << "\n" << gif.output;
  }
  EXPECT_NE(c.output.find("static const uint64_t vbim_lightmap_draw[20][2] __attribute__((aligned(16))) = {"),
            std::string::npos)
      << c.output;
  const auto md = vbim("config --gs-setup --stream " + kSample);
  EXPECT_NE(md.output.find("| 8 | `ALPHA_1` | 0x42 | `0x4000000064` |"), std::string::npos) << md.output;
  EXPECT_NE(vbim("config --format gif --stream " + kSample).output.find("--format requires --gs-setup"),
            std::string::npos);
}

TEST_F(ConfigCheckCli, AStreamThatIsNotOneIsNamed) {
  const std::string cfg = config("gs.fix = 64\n");
  const fs::path junk = dir_ / "junk.vbim";
  ASSERT_TRUE(writeTextFile(junk, std::string(4096, 'x')));
  const std::string r = refusal(vbim("config --check " + cfg + " --stream " + junk.string()), "config");
  EXPECT_NE(r.find(junk.string()), std::string::npos) << r;
}

}  // namespace
