// `vbim decode` as a call (runs/decode_run.hpp) on the committed sample: every picture written as a
// file with one observer call each, the summary line, and the refusals (a stream id the stream does
// not hold, an existing output) that leave nothing behind.
#include "runs/decode_run.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

std::size_t filesIn(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
  return n;
}

// The sample decoded into `dir`/frames.
DecodeRequest sampleInto(const fs::path& dir) {
  DecodeRequest r;
  r.input = kSample;
  r.out = (dir / "frames").string();
  return r;
}

TEST(DecodeRun, EveryPictureIsAFileAndTheLineSaysHowMany) {
  const fs::path dir = vbim::testing::testScratchDir("decode_run");
  DecodeRequest r = sampleInto(dir);
  r.format = "yuv";
  int pictures = 0;
  DecodeObserver observer;
  observer.onPicture = [&pictures] { ++pictures; };
  observer.onReport = [](const std::string& line) { ADD_FAILURE() << "the sample decodes cleanly: " << line; };
  const DecodeResult result = decodeRun(r, observer);
  EXPECT_EQ(result.strictFailure, "");
  const std::string& line = result.summary;
  ASSERT_GT(pictures, 0);
  EXPECT_EQ(filesIn(r.out), static_cast<std::size_t>(pictures));
  EXPECT_EQ(line.rfind("decoded " + std::to_string(pictures) + " pictures ", 0), 0u) << line;
  EXPECT_NE(line.find(" to " + r.out + "/ as yuv\n"), std::string::npos) << line;
  // The same output again is refused before any picture is decoded.
  pictures = 0;
  EXPECT_THROW(decodeRun(r, observer), Error);
  EXPECT_EQ(pictures, 0);
  fs::remove_all(dir);
}

TEST(DecodeRun, AStreamIdTheStreamDoesNotHoldWritesNothing) {
  const fs::path dir = vbim::testing::testScratchDir("decode_run");
  DecodeRequest r = sampleInto(dir);
  r.streamId = "0xEF";
  EXPECT_THROW(decodeRun(r, {}), Error);
  EXPECT_FALSE(fs::exists(r.out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::runs
