// vbim replay --frames DIR (docs/porting.md, "Replay with the port's frames"): the GS side fed with
// a port's decoded frames instead of vbim's decode. Frames written by `vbim decode --format rgba`
// reproduce the replay's (and play's) hashes; a changed frame gives the first vsync that differs;
// a missing or short frame file is named with what was expected, before anything is written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

// From the source tree: the tests name the samples by their paths in it.
Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_BINARY, args, VBIM_SOURCE_DIR);
}

class ReplayFrames : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = vbim::testing::testScratchDir("replay_frames_test"); }
  void TearDown() override { fs::remove_all(dir_); }

  // Plays `stream` with `args`, and decodes both its streams to DIR/frames as a port would dump them.
  void playAndDecode(const std::string& stream, const std::string& args) {
    const Result p = run("play " + stream + " " + args + " --no-trace --out " + (dir_ / "play").string());
    ASSERT_EQ(p.status, 0) << p.output;
    for (const auto& [id, name] : {std::pair{"0xE0", "lightmap"}, std::pair{"0xE1", "sky"}}) {
      const Result d =
          run("decode " + stream + " --format rgba --stream-id " + id + " --out " + (dir_ / "frames" / name).string());
      ASSERT_EQ(d.status, 0) << d.output;
    }
  }
  Result replay(const std::string& stream, const std::string& out, const std::string& extra) {
    return run("replay " + stream + " --arrivals " + (dir_ / "play/arrivals.csv").string() + " --out " +
               (dir_ / out).string() + " " + extra);
  }
  void expectSameHashesWithAndWithoutFrames(const std::string& stream) {
    const Result own = replay(stream, "own", "");
    ASSERT_EQ(own.status, 0) << own.output;
    const Result port =
        replay(stream, "port", "--frames " + (dir_ / "frames").string() + " --compare " + (dir_ / "play").string());
    ASSERT_EQ(port.status, 0) << port.output;
    EXPECT_NE(port.output.find("with the frames of " + (dir_ / "frames").string()), std::string::npos) << port.output;
    EXPECT_NE(port.output.find("every hash equals"), std::string::npos) << port.output;
    const std::string hashes = vbim::testing::readFileBytes(dir_ / "port/hashes.txt");
    EXPECT_FALSE(hashes.empty());
    EXPECT_EQ(hashes, vbim::testing::readFileBytes(dir_ / "own/hashes.txt"));
    EXPECT_EQ(hashes, vbim::testing::readFileBytes(dir_ / "play/hashes.txt"));
  }
  fs::path dir_;
};

// A loop wrap (day_clear has 24 frames at 1 a second) and both streams.
TEST_F(ReplayFrames, FramesDecodedByVbimReproduceTheHashesAcrossALoopWrap) {
  playAndDecode("streams/samples/day_clear.vbim", "--duration 30s");
  expectSameHashesWithAndWithoutFrames("streams/samples/day_clear.vbim");
}

// A branch to the second variant: its pictures are numbered after the first variant's.
TEST_F(ReplayFrames, FramesDecodedByVbimReproduceTheHashesAcrossABranch) {
  playAndDecode("streams/samples/day_weather.vbim", "--duration 20s --branch 8s=1");
  const std::string arrivals = vbim::testing::readFileBytes(dir_ / "play/arrivals.csv");
  ASSERT_NE(arrivals.find("lightmap:1,"), std::string::npos) << arrivals;
  expectSameHashesWithAndWithoutFrames("streams/samples/day_weather.vbim");
}

// A stream with P and B pictures that loops to frame 4 and branches: `vbim decode` numbers its
// pictures in display order, as replay names them.
TEST_F(ReplayFrames, FramesDecodedByVbimReproduceTheHashesOfAGopStream) {
  const std::string stream = (dir_ / "gop.vbim").string();
  const Result a =
      run("author --synthetic clear,overcast --synthetic-frames 16 --synthetic-size 128x128 --synthetic-sky-size 64x32 "
          "--gop 6 --b-frames 2 --loop 4 --out " +
          stream);
  ASSERT_EQ(a.status, 0) << a.output;
  playAndDecode(stream, "--duration 40s --branch 9s=1");
  expectSameHashesWithAndWithoutFrames(stream);
}

TEST_F(ReplayFrames, AChangedFrameGivesTheFirstDifferingVsync) {
  playAndDecode("streams/samples/day_clear.vbim", "--duration 10s");
  {
    // One byte of lightmap frame 3, which arrives at vsync 151 and is due (becomes the target) at 210.
    std::fstream f(dir_ / "frames/lightmap/frame_00003.rgba", std::ios::binary | std::ios::in | std::ios::out);
    f.seekg(1000);
    const int byte = f.get();
    f.seekp(1000);
    f.put(static_cast<char>(byte ^ 0x40));
  }
  const Result r = replay("streams/samples/day_clear.vbim", "changed",
                          "--frames " + (dir_ / "frames").string() + " --compare " + (dir_ / "play").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("first difference at vsync 210 (3.503500 s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lightmap: frame 3 due, target frame 3"), std::string::npos) << r.output;
}

TEST_F(ReplayFrames, AMissingOrShortFrameIsNamedWithWhatWasExpected) {
  playAndDecode("streams/samples/day_clear.vbim", "--duration 10s");
  const fs::path sky2 = dir_ / "frames/sky/frame_00002.rgba";
  fs::remove(sky2);
  Result r = replay("streams/samples/day_clear.vbim", "missing", "--frames " + (dir_ / "frames").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(sky2.string() + ": missing: the sky picture 2 (variant 0, timeline frame 2)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("expected 128x64 RGB32, 32768 bytes"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  const fs::path lm0 = dir_ / "frames/lightmap/frame_00000.rgba";
  fs::resize_file(lm0, 262143);
  r = replay("streams/samples/day_clear.vbim", "short", "--frames " + (dir_ / "frames").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(lm0.string() + ": 262143 bytes: the lightmap picture 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("expected 256x256 RGB32, 262144 bytes"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "short"));
}

}  // namespace
