// streams/authoring/frame_author: `vbim author --frames/--synthetic` as a call: the synthetic day
// written and described, and a request with no source, both sources or a bad size refused by name
// before anything is written.
#include "streams/authoring/frame_author.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "streams/authoring/error.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vbim::streams;

FrameAuthorRequest smallSyntheticDay() {
  FrameAuthorRequest r;
  r.synthetic = "clear";
  r.syntheticFrames = 2;
  r.syntheticSize = "32x32";
  r.syntheticSkySize = "0x0";
  return r;
}

std::string refusal(const FrameAuthorRequest& r, const std::string& out) {
  try {
    authorFrameStream(r, out);
  } catch (const AuthoringError& e) {
    return e.what();
  }
  return "";
}

TEST(FrameAuthor, TheSyntheticDayIsWrittenAndItsSizeSaid) {
  const fs::path dir = vbim::testing::testScratchDir("frame_author");
  const std::string out = (dir / "day.vbim").string();
  std::size_t reported = 0;
  const std::string lines = authorFrameStream(smallSyntheticDay(), out, [&](const FrameAuthorProgress& p) {
    reported = p.done;
    EXPECT_EQ(p.total, 2u);
  });
  EXPECT_EQ(reported, 2u);
  const auto bytes = fs::file_size(out);
  EXPECT_EQ(bytes % 2048, 0u);
  EXPECT_EQ(lines, out + ": " + std::to_string(bytes / 2048) + " sectors (" + std::to_string(bytes) + " bytes)\n");
  fs::remove_all(dir);
}

TEST(FrameAuthor, NoSourceBothSourcesAndBadSizesAreRefusedByName) {
  const fs::path dir = vbim::testing::testScratchDir("frame_author");
  const std::string out = (dir / "day.vbim").string();
  EXPECT_EQ(refusal(FrameAuthorRequest{}, out),
            "give a source: --frames PATTERN, --terrain FILE or --procedural (Technique A), or --synthetic");
  FrameAuthorRequest both = smallSyntheticDay();
  both.sequences.frames = "lm_%04d.png";
  EXPECT_EQ(refusal(both, out), "--synthetic replaces --frames and --variant; give one or the other");
  FrameAuthorRequest badSize = smallSyntheticDay();
  badSize.syntheticSkySize = "64";
  EXPECT_EQ(refusal(badSize, out), "--synthetic-sky-size '64': expected WxH");
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
