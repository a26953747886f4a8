// ISO 9660 images wherever a stream works (issue #15 item 6): `vbim info|play|decode|profile
// disc.iso`, the stream picked with --file or by default, the same frames as the bare stream, and
// the drive reading the file where the image holds it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::readFileBytes;
using vbim::testing::runCommand;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

class DiscImageCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = vbim::testing::testScratchDir("disc_image_cli");
    fs::create_directories(dir_ / "root" / "DATA");
    // A level file before the stream, so the stream lies well away from where a bare one would.
    std::ofstream(dir_ / "root" / "DATA" / "AAA.BIN") << std::string(3 << 20, '\0');
    fs::copy_file(kSample, dir_ / "root" / "DATA" / "DAY.VBI");
    iso_ = dir_ / "disc.iso";
    const auto r =
        runCommand("xorriso -as mkisofs -quiet -o '" + iso_.string() + "' '" + (dir_ / "root").string() + "'");
    ASSERT_EQ(r.status, 0) << r.output;
  }
  void TearDown() override { fs::remove_all(dir_); }

  vbim::testing::CommandResult vbim(const std::string& args) const {
    return runCommand(std::string(VBIM_BINARY) + " " + args);
  }

  fs::path dir_, iso_;
};

TEST_F(DiscImageCli, InfoShowsTheStreamOnTheImageAsOnItsOwn) {
  const auto text = vbim("info " + iso_.string());
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find(iso_.string() + " \\DATA\\DAY.VBI;1 (LBA "), std::string::npos) << text.output;
  const auto onImage = vbim("info --json --file '\\DATA\\DAY.VBI;1' " + iso_.string());
  const auto bare = vbim("info --json " + kSample);
  ASSERT_EQ(onImage.status, 0) << onImage.output;
  ASSERT_EQ(bare.status, 0) << bare.output;
  nlohmann::json a = nlohmann::json::parse(onImage.output), b = nlohmann::json::parse(bare.output);
  EXPECT_EQ(a["disc_file"]["path"], "\\DATA\\DAY.VBI;1");
  EXPECT_GT(a["disc_file"]["lba"].get<int>(), 1536);  // past the 3 MB level file
  for (const char* k : {"bytes", "descriptor", "streams", "errors"}) EXPECT_EQ(a[k], b[k]) << k;
}

TEST_F(DiscImageCli, DecodeAndPlayGiveTheBareStreamsFrames) {
  ASSERT_EQ(vbim("decode " + iso_.string() + " --out " + (dir_ / "dec_iso").string()).status, 0);
  ASSERT_EQ(vbim("decode " + kSample + " --out " + (dir_ / "dec_bare").string()).status, 0);
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "dec_bare")) {
    EXPECT_EQ(readFileBytes(dir_ / "dec_iso" / e.path().filename()), readFileBytes(e.path())) << e.path();
    ++frames;
  }
  EXPECT_EQ(frames, 24);

  const auto play = vbim("play " + iso_.string() + " --duration 30s --no-trace --out " + (dir_ / "run_iso").string());
  ASSERT_EQ(play.status, 0) << play.output;
  EXPECT_NE(play.output.find("of " + iso_.string() + " \\DATA\\DAY.VBI;1 (LBA "), std::string::npos) << play.output;
  ASSERT_EQ(vbim("play " + kSample + " --duration 30s --no-trace --out " + (dir_ / "run_bare").string()).status, 0);
  // The stream is read at 1 frame/s, far below the drive's rate: the same frame at every vsync.
  EXPECT_EQ(readFileBytes(dir_ / "run_iso" / "hashes.txt"), readFileBytes(dir_ / "run_bare" / "hashes.txt"));
}

// replay takes an image as play does: the arrivals of a play of the image, replayed from the image,
// give its hashes.txt; a name that is not on the image is refused with the candidates.
TEST_F(DiscImageCli, ReplayReadsTheStreamFromTheImage) {
  const auto play = vbim("play " + iso_.string() + " --duration 12s --no-trace --out " + (dir_ / "run").string());
  ASSERT_EQ(play.status, 0) << play.output;
  const auto replay = vbim("replay " + iso_.string() + " --file '\\DATA\\DAY.VBI;1' --arrivals " +
                           (dir_ / "run" / "arrivals.csv").string() + " --out " + (dir_ / "replayed").string());
  ASSERT_EQ(replay.status, 0) << replay.output;
  EXPECT_EQ(readFileBytes(dir_ / "replayed" / "hashes.txt"), readFileBytes(dir_ / "run" / "hashes.txt"));
  const auto missing = vbim("replay " + iso_.string() + " --file '\\DATA\\NIGHT.VBI;1' --arrivals " +
                            (dir_ / "run" / "arrivals.csv").string() + " --out " + (dir_ / "none").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("DAY.VBI"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(dir_ / "none"));
}

// A fault plan that names a file on the image is checked against the image given with --stream, as
// play would; without a disc the name cannot be looked up and the message says so.
TEST_F(DiscImageCli, ConfigChecksAFaultPlansFileNamesOnTheStreamsDisc) {
  const fs::path plan = dir_ / "plan.toml";
  std::ofstream(plan) << "[[fault]]\nkind = 'seek_away'\nat = '1s'\nfile = '\\DATA\\AAA.BIN;1'\nsectors = 16\n";
  const auto ok = vbim("config --faults " + plan.string() + " --stream " + iso_.string());
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_NE(ok.output.find("1 fault(s), valid"), std::string::npos) << ok.output;
  const auto noDisc = vbim("config --faults " + plan.string());
  EXPECT_EQ(noDisc.status, 2);
  EXPECT_NE(noDisc.output.find("needs a disc"), std::string::npos) << noDisc.output;
  const fs::path wrong = dir_ / "wrong.toml";
  std::ofstream(wrong) << "[[fault]]\nkind = 'seek_away'\nat = '1s'\nfile = '\\DATA\\NIGHT.BIN;1'\nsectors = 16\n";
  const auto missing = vbim("config --faults " + wrong.string() + " --stream " + iso_.string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("no file '\\DATA\\NIGHT.BIN;1'"), std::string::npos) << missing.output;
}

// A scratched sector at the stream's LBA on the image costs retries; the same LBA in a bare run
// (where the stream starts at LBA 2048) lies outside the stream and costs none.
TEST_F(DiscImageCli, TheDriveReadsTheFileAtTheImagesLbas) {
  const auto info = vbim("info --json " + iso_.string());
  ASSERT_EQ(info.status, 0) << info.output;
  const int lba = nlohmann::json::parse(info.output)["disc_file"]["lba"].get<int>() + 20;
  ASSERT_LT(lba, 2048);
  const fs::path plan = dir_ / "scratch.toml";
  std::ofstream(plan) << "[[fault]]\nkind = \"read_error\"\nlba = " << lba << "\nattempts = 3\n";
  // The count after "drive retries " in play's summary ("" when absent). Plain string search: GCC 12
  // warns falsely inside <regex> in the -O1 sanitizer build, which -Werror turns into an error.
  const auto retries = [](const std::string& out) {
    const std::string key = "drive retries ";
    const auto at = out.find(key);
    if (at == std::string::npos) return std::string();
    const auto begin = at + key.size();
    return out.substr(begin, out.find_first_not_of("0123456789", begin) - begin);
  };
  const auto onImage = vbim("play " + iso_.string() + " --faults " + plan.string() +
                            " --duration 30s --no-trace --out " + (dir_ / "a").string());
  ASSERT_EQ(onImage.status, 0) << onImage.output;
  EXPECT_EQ(retries(onImage.output), "3") << onImage.output;
  const auto bare = vbim("play " + kSample + " --faults " + plan.string() + " --duration 30s --no-trace --out " +
                         (dir_ / "b").string());
  ASSERT_EQ(bare.status, 0) << bare.output;
  EXPECT_EQ(retries(bare.output), "0") << bare.output;
}

TEST_F(DiscImageCli, AMissingFileIsRefusedWithTheCandidates) {
  for (const char* cmd : {"info", "play", "decode", "profile"}) {
    const std::string out = std::string(cmd) == "info" ? "" : " --out " + (dir_ / (std::string("o_") + cmd)).string();
    const auto r = vbim(std::string(cmd) + " " + iso_.string() + " --file '\\DATA\\NIGHT.VBI;1'" + out);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find(iso_.string() + ": no file '\\DATA\\NIGHT.VBI;1' on the disc image; its VBIM streams "
                                            "are:\n  \\DATA\\DAY.VBI;1 (LBA "),
              std::string::npos)
        << cmd << ": " << r.output;
  }
}

TEST_F(DiscImageCli, ProfileSweepsTheStreamOnTheImage) {
  const auto r =
      vbim("profile " + iso_.string() + " --ring 4:8 --no-search --duration 3s --out " + (dir_ / "prof").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(readFileBytes(dir_ / "prof" / "sweep.csv").find("disc,"), std::string::npos);
}

}  // namespace
