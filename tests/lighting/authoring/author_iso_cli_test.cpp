// `vbim author ... --iso disc.iso` (issue #15 item 6): the authored stream on an ISO 9660 image that
// info, decode and play read as they read the bare stream, the same image bytes from the same
// stream, and names level 1 cannot hold refused before any work.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::readFileBytes;
using vbim::testing::runCommand;

class AuthorIsoCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vbim_author_iso_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  vbim::testing::CommandResult vbim(const std::string& args) const {
    return runCommand(std::string(VBIM_BINARY) + " " + args);
  }
  std::string p(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

const std::string kDay = "author --synthetic clear,overcast --synthetic-frames 8 --fps 1 ";

TEST_F(AuthorIsoCli, TheImageHoldsTheStreamThatInfoDecodeAndPlayRead) {
  const auto a = vbim(kDay + "--out " + p("day.vbim") + " --iso " + p("disc.iso"));
  ASSERT_EQ(a.status, 0) << a.output;
  EXPECT_NE(a.output.find(p("disc.iso") + ": ISO 9660 image, \\DATA\\DAY.VBI;1 at LBA "), std::string::npos)
      << a.output;

  const auto onImage = vbim("info --json " + p("disc.iso"));
  const auto bare = vbim("info --json " + p("day.vbim"));
  ASSERT_EQ(onImage.status, 0) << onImage.output;
  ASSERT_EQ(bare.status, 0) << bare.output;
  const auto ji = nlohmann::json::parse(onImage.output), jb = nlohmann::json::parse(bare.output);
  EXPECT_EQ(ji["disc_file"]["path"], "\\DATA\\DAY.VBI;1");
  EXPECT_EQ(ji["disc_file"]["bytes"], fs::file_size(dir_ / "day.vbim"));
  for (const char* k : {"descriptor", "streams", "errors"}) EXPECT_EQ(ji[k], jb[k]) << k;

  ASSERT_EQ(vbim("decode " + p("disc.iso") + " --file '\\DATA\\DAY.VBI;1' --out " + p("dec_iso")).status, 0);
  ASSERT_EQ(vbim("decode " + p("day.vbim") + " --out " + p("dec_bare")).status, 0);
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "dec_bare")) {
    EXPECT_EQ(readFileBytes(dir_ / "dec_iso" / e.path().filename()), readFileBytes(e.path())) << e.path();
    ++frames;
  }
  EXPECT_EQ(frames, 16);

  const auto play = vbim("play " + p("disc.iso") + " --duration 20s --branch 9s=1 --no-trace --out " + p("run_iso"));
  ASSERT_EQ(play.status, 0) << play.output;
  ASSERT_EQ(vbim("play " + p("day.vbim") + " --duration 20s --branch 9s=1 --no-trace --out " + p("run_bare")).status,
            0);
  EXPECT_EQ(readFileBytes(dir_ / "run_iso" / "hashes.txt"), readFileBytes(dir_ / "run_bare" / "hashes.txt"));
}

// The same stream gives the same image, whenever it is written (dates from SOURCE_DATE_EPOCH).
TEST_F(AuthorIsoCli, TheSameStreamGivesTheSameImageBytes) {
  ASSERT_EQ(vbim(kDay + "--out " + p("a.vbim") + " --iso " + p("a.iso")).status, 0);
  fs::last_write_time(dir_ / "a.vbim", fs::last_write_time(dir_ / "a.vbim") - std::chrono::hours(50));
  ASSERT_EQ(vbim(kDay + "--out " + p("b.vbim") + " --iso " + p("b.iso")).status, 0);
  const std::string a = readFileBytes(dir_ / "a.iso");
  EXPECT_GT(a.size(), fs::file_size(dir_ / "a.vbim"));
  EXPECT_TRUE(a == readFileBytes(dir_ / "b.iso")) << "the two images differ";
}

TEST_F(AuthorIsoCli, NamesLevelOneCannotHoldAreRefusedBeforeAnyWork) {
  const auto longName = vbim(kDay + "--out " + p("x.vbim") + " --iso " + p("x.iso") + " --iso-file '\\DATA\\DAY.VBIM'");
  EXPECT_EQ(longName.status, 2) << longName.output;
  EXPECT_NE(longName.output.find("--iso-file '\\DATA\\DAY.VBIM': 'DAY.VBIM': an extension has up to 3 characters"),
            std::string::npos)
      << longName.output;
  const auto same = vbim(kDay + "--out " + p("x.vbim") + " --iso " + p("x.vbim"));
  EXPECT_EQ(same.status, 2) << same.output;
  EXPECT_NE(same.output.find("is the --out stream file"), std::string::npos) << same.output;
  EXPECT_TRUE(fs::is_empty(dir_)) << "left behind: " << fs::directory_iterator(dir_)->path();
}

}  // namespace
