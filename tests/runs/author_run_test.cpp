// `vbim author` as a call (runs/author_run.hpp): a synthetic day written with its progress and its
// lines, and what is refused before any encoding (an existing output, --iso naming the stream,
// Technique A beside the other sources' options). Disc images (xorriso) end to end are tests/cli's.
#include "runs/author_run.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

AuthorRequest smallSyntheticDay(const fs::path& out) {
  AuthorRequest r;
  r.frames.synthetic = "clear";
  r.frames.syntheticFrames = 2;
  r.frames.syntheticSize = "32x32";
  r.frames.syntheticSkySize = "32x16";
  r.out = out.string();
  return r;
}

TEST(AuthorRun, ASyntheticDayIsWrittenWithItsProgressAndLines) {
  const fs::path dir = vbim::testing::testScratchDir("author_run");
  const AuthorRequest r = smallSyntheticDay(dir / "day.vbim");
  double lastDone = 0, lastTotal = 0;
  std::string text;
  AuthorObserver observer;
  observer.onProgress = [&](double done, double total, const std::string&) {
    lastDone = done;
    lastTotal = total;
  };
  observer.onText = [&text](const std::string& t) { text += t; };
  authorRun(r, observer);
  EXPECT_GT(fs::file_size(r.out), 0u);
  EXPECT_EQ(lastDone, lastTotal);
  EXPECT_GT(lastTotal, 0);
  EXPECT_NE(text.find(r.out), std::string::npos) << text;
  // Again over the same file: refused before any frame.
  lastTotal = 0;
  EXPECT_THROW(authorRun(r, observer), Error);
  EXPECT_EQ(lastTotal, 0);
  fs::remove_all(dir);
}

TEST(AuthorRun, ConflictingRequestsAreRefusedBeforeAnyEncoding) {
  const fs::path dir = vbim::testing::testScratchDir("author_run");
  AuthorObserver observer;
  observer.onProgress = [](double, double, const std::string&) { ADD_FAILURE() << "nothing is encoded"; };
  AuthorRequest iso = smallSyntheticDay(dir / "day.vbim");
  iso.iso = iso.out;
  EXPECT_THROW(authorRun(iso, observer), Error);
  AuthorRequest isoFile = smallSyntheticDay(dir / "day.vbim");
  isoFile.iso = (dir / "day.iso").string();
  isoFile.isoFile = "\\a-name-far-too-long-for-level-1.vbim;1";
  EXPECT_THROW(authorRun(isoFile, observer), Error);
  AuthorRequest both = smallSyntheticDay(dir / "day.vbim");
  both.technique = "--procedural";
  try {
    authorRun(both, observer);
    ADD_FAILURE() << "Technique A with --synthetic was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--procedural selects Technique A"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "day.vbim"));
  EXPECT_FALSE(fs::exists(dir / "day.iso"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::runs
