// A run that stops showing frames is reported as such (issue #15, docs/player.md "Stuck and starved
// runs"): `vbim play` warns on stderr and in its summary and records stats.json "health"; `vbim
// profile` flags the case on its line and in sweep.csv. The simulation completed, so both exit 0.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::readFileBytes;
using vbim::testing::runCommand;
using vbim::testing::writeTextFile;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

class HealthCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = vbim::testing::testScratchDir("health_cli"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) const {
    EXPECT_TRUE(writeTextFile(dir_ / name, text));
    return (dir_ / name).string();
  }
  // A drive stall from `at` that outlasts the run.
  std::string stallFrom(const std::string& at) const {
    return file("stall.toml", "[[fault]]\nkind = \"stall\"\nat = \"" + at + "\"\nduration = \"600s\"\n");
  }
  static vbim::testing::CommandResult vbim(const std::string& args) {
    return runCommand(std::string(VBIM_BINARY) + " " + args);
  }
  std::string stats(const std::string& run) const { return readFileBytes(dir_ / run / "stats.json"); }

  fs::path dir_;
};

TEST_F(HealthCli, PlayReportsARunThatNeverShowsAFrameAsStarved) {
  const auto r = vbim("play " + kSample + " --faults " + stallFrom("0s") + " --duration 12s --no-trace --out " +
                      (dir_ / "run").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("vbim play: warning: starved run: no frame was ever shown"), std::string::npos) << r.output;
  EXPECT_NE(stats("run").find("\"verdict\": \"starved\""), std::string::npos) << stats("run");
}

// A 4-bank ring of 8 sectors holds too little to ride out a stall that lasts the rest of the run.
TEST_F(HealthCli, PlayReportsADisplayThatStopsAsStuck) {
  const std::string cfg = file("ring.toml", "ring.bankmax = 4\nring.bufmax_sectors = 8\n");
  const auto r = vbim("play " + kSample + " --config " + cfg + " --faults " + stallFrom("4s") +
                      " --duration 15s --no-trace --out " + (dir_ / "run").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("vbim play: warning: stuck run: the display stopped"), std::string::npos) << r.output;
  const std::string s = stats("run");
  EXPECT_NE(s.find("\"verdict\": \"stuck\""), std::string::npos) << s;
  EXPECT_NE(s.find("\"stuck_after_s\": 5.0"), std::string::npos) << s;
}

TEST_F(HealthCli, AHealthyRunIsOkAndQuiet) {
  const auto r = vbim("play " + kSample + " --duration 12s --no-trace --out " + (dir_ / "run").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  const std::string s = stats("run");
  EXPECT_NE(s.find("\"verdict\": \"ok\""), std::string::npos) << s;
  EXPECT_NE(s.find("\"stuck_s\": 0.0"), std::string::npos) << s;
}

TEST_F(HealthCli, ProfileFlagsEachStuckCase) {
  const auto r = vbim("profile " + kSample + " --ring 4:8,5:160 --faults " + stallFrom("4s") +
                      " --duration 15s --no-search --out " + (dir_ / "prof").string());
  EXPECT_EQ(r.status, 0) << r.output;
  // The flag ends the stuck case's own line (the figures before it depend on the sample's bytes).
  const auto stuckLine = r.output.find("ring 4:8  faults stall  blend-through: late 0, pop max ");
  ASSERT_NE(stuckLine, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("  STUCK\n", stuckLine), r.output.find('\n', stuckLine) - 7) << r.output;
  EXPECT_NE(r.output.find("vbim profile: day_clear ring 4:8 blend-through: warning: stuck run"), std::string::npos)
      << r.output;
  // Each line counts the runs, as plan mode's progress does: 2 rings x (no faults, the stall).
  EXPECT_NE(r.output.find("[1/4, "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\n[4/4, 0 s left] sweep  day_clear  ring 5:160  faults stall"), std::string::npos)
      << r.output;
  const std::string csv = readFileBytes(dir_ / "prof" / "sweep.csv");
  EXPECT_NE(csv.find(",frames_lost,health\n"), std::string::npos) << csv;
  const auto stuckRow = csv.find(",4,8,stall,blend-through,");
  ASSERT_NE(stuckRow, std::string::npos) << csv;
  EXPECT_EQ(csv.find(",stuck\n", stuckRow), csv.find('\n', stuckRow) - 6) << csv;
  EXPECT_NE(csv.find(",ok\n"), std::string::npos) << csv;
}

}  // namespace
