// Replay shows after a loop wrap the frame play shows: the descriptor's loop frame (here 1), not
// frame 0. Replay once took timeline frame k as stream frame k mod F, which is frame 0 after a wrap.
#include <gtest/gtest.h>

#include <string>

#include "tests/streams/stream_fixture.hpp"
#include "tests/support/run_command.hpp"

namespace vbim::streams::test {
namespace {

TEST(ReplayLoop, ReplayOfAStreamLoopingToFrame1ReproducesPlay) {
  const SmallStream& s = smallStream(4, 1);  // 2 frames a game second, loop frame 1
  ASSERT_EQ(s.descriptor.loopFrame, 1u);
  TempDir dir;
  const auto file = dir.path() / "loop.vbim";
  writeFile(file, s.bytes);
  // 6 s: frames 0-3, then 1, 2, 3, 1, 2, ... (seq 4 shows frame 1 from 2.5 s on).
  const auto play = vbim::testing::runCommand(std::string(VBIM_BINARY) + " play " + file.string() +
                                              " --duration 6s --no-trace --out " + (dir.path() / "play").string());
  ASSERT_EQ(play.status, 0) << play.output;
  const auto replay =
      vbim::testing::runCommand(std::string(VBIM_BINARY) + " replay " + file.string() + " --arrivals " +
                                (dir.path() / "play/arrivals.csv").string() + " --compare " +
                                (dir.path() / "play").string() + " --out " + (dir.path() / "replay").string());
  EXPECT_EQ(replay.status, 0) << replay.output;
  EXPECT_NE(replay.output.find("every hash equals"), std::string::npos) << replay.output;
  EXPECT_EQ(vbim::testing::readFileBytes(dir.path() / "replay/hashes.txt"),
            vbim::testing::readFileBytes(dir.path() / "play/hashes.txt"));
}

}  // namespace
}  // namespace vbim::streams::test
