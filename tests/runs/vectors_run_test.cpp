// A port's vector files scored against the vectors (runs/vectors_run.hpp), on small hand-made
// files: what each kind of difference counts as, what --only selects, and the written directory.
#include "runs/vectors_run.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

const std::vector<player::VectorFile> kVectors{
    {"vlc.txt", "# header\nvlc/a/mb=0 q=1\nvlc/a/mb=1 q=2\nvlc/b/mb=0 q=3\n"},
    {"csc.txt", "# header\ncsc/a/rgb32 0a,0b,0c,0d\n"},
};

fs::path portWith(const std::string& test, const std::string& vlc, const std::string& csc) {
  const fs::path d = vbim::testing::scratchDir("vectors_run_" + test);
  if (!vlc.empty()) std::ofstream(d / "vlc.txt") << vlc;
  if (!csc.empty()) std::ofstream(d / "csc.txt") << csc;
  return d;
}

TEST(CheckVectors, EqualFilesPass) {
  const fs::path d = portWith("equal", kVectors[0].text, kVectors[1].text);
  const VectorsCheck c = checkVectors(kVectors, d, {});
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.present, 2u);
  EXPECT_EQ(c.checked, 4u);
  EXPECT_EQ(c.matched, 4u);
  EXPECT_EQ(c.report, "  vlc.txt: 3 of 3 match (pass)\n  csc.txt: 1 of 1 match (pass)\n");
  fs::remove_all(d);
}

TEST(CheckVectors, DifferencesAreCountedAndTheFirstNamedWithWhereInTheValue) {
  const fs::path d =
      portWith("differ", "vlc/a/mb=0 q=9\nvlc/b/mb=0 q=3\nvlc/c/mb=0 q=1\n", "csc/a/rgb32 0a,0b,ff,0d\n");
  const VectorsCheck c = checkVectors(kVectors, d, {});
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.present, 2u);
  EXPECT_EQ(c.matched, 1u);
  EXPECT_NE(c.report.find("  vlc.txt: 1 of 3 match, 1 differ, 1 missing, 1 not in the vectors (fail)\n"),
            std::string::npos)
      << c.report;
  EXPECT_NE(c.report.find("    " + (d / "vlc.txt").string() + ": entry 'vlc/a/mb=0': expected 'q=1', found 'q=9'\n"),
            std::string::npos)
      << c.report;
  EXPECT_NE(c.report.find("element 2 of 4: expected '0c', found 'ff'"), std::string::npos) << c.report;
  fs::remove_all(d);
}

TEST(CheckVectors, AnAbsentFileIsNamedNotFailed) {
  const fs::path d = portWith("absent", kVectors[0].text, "");
  const VectorsCheck c = checkVectors(kVectors, d, {});
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.present, 1u);
  EXPECT_NE(c.report.find("  csc.txt: no such file, absent (1 entries not checked)\n"), std::string::npos) << c.report;
  fs::remove_all(d);
}

TEST(CheckVectors, OnlySelectsStagesOrKeys) {
  const fs::path d = portWith("only", "vlc/a/mb=0 q=1\nvlc/a/mb=1 q=2\nvlc/b/mb=0 q=7\n", kVectors[1].text);
  // A stage name selects its whole file: the differing vlc/b entry is outside csc.
  const VectorsCheck stage = checkVectors(kVectors, d, {"csc"});
  EXPECT_TRUE(stage.passed);
  EXPECT_EQ(stage.checked, 1u);
  EXPECT_NE(stage.report.find("  vlc.txt: no entry selected\n"), std::string::npos) << stage.report;
  // A key pattern selects entries in any file.
  const VectorsCheck keys = checkVectors(kVectors, d, {"vlc/a/*"});
  EXPECT_TRUE(keys.passed);
  EXPECT_EQ(keys.checked, 2u);
  EXPECT_FALSE(checkVectors(kVectors, d, {"vlc/b/*"}).passed);
  // Stages alone or comma-separated; something that is no stage is a pattern.
  EXPECT_EQ(checkVectors(kVectors, d, {"vlc,csc"}).checked, 4u);
  const VectorsCheck none = checkVectors(kVectors, d, {"nothing/*"});
  EXPECT_EQ(none.present, 0u);
  EXPECT_FALSE(none.anySelected);
  fs::remove_all(d);
}

TEST(WriteVectors, WritesEveryFileAndCountsItsLines) {
  const fs::path out = vbim::testing::scratchPath("vectors_run_write");
  EXPECT_EQ(writeVectors(kVectors, out.string(), false), 6u);
  EXPECT_EQ(vbim::testing::readFileBytes(out / "vlc.txt"), kVectors[0].text);
  EXPECT_EQ(vbim::testing::readFileBytes(out / "csc.txt"), kVectors[1].text);
  // An existing output is refused without force.
  EXPECT_THROW(writeVectors(kVectors, out.string(), false), Error);
  fs::remove_all(out);
}

// What the command's Ctrl-C check throws after the files are written leaves no directory: the
// signal that came last is not lost to a rename (vbim vectors exits 130, not 0).
TEST(WriteVectors, AThrowBeforeTheCommitLeavesNoDirectory) {
  const fs::path out = vbim::testing::scratchPath("vectors_run_stopped");
  bool called = false;
  EXPECT_THROW(writeVectors(kVectors, out.string(), false,
                            [&called] {
                              called = true;
                              throw std::runtime_error("interrupted");
                            }),
               std::runtime_error);
  EXPECT_TRUE(called);
  EXPECT_FALSE(fs::exists(out));
}

std::string requestRefusal(const std::string& out, const std::string& check, const std::vector<std::string>& only) {
  try {
    checkVectorsRequest(out, check, only, false);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// vectorsRun's checkpoint is called once the vectors are computed and again before the rename; a
// throw from either leaves no directory (the command's Ctrl-C: exit 130, nothing written).
TEST(VectorsRun, TheCheckpointComesBeforeAnyOutputAndBeforeTheRename) {
  const fs::path out = vbim::testing::scratchPath("vectors_run_checkpoint");
  VectorsRequest r;
  r.streams = {std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim"};
  r.out = out.string();
  for (const int stopAt : {1, 2}) {
    int calls = 0;
    EXPECT_THROW(vectorsRun(r,
                            [&] {
                              if (++calls == stopAt) throw std::runtime_error("interrupted");
                              EXPECT_FALSE(fs::exists(out)) << "before the rename";
                            }),
                 std::runtime_error);
    EXPECT_EQ(calls, stopAt);
    EXPECT_FALSE(fs::exists(out));
  }
  int calls = 0;
  const VectorsVerdict v = vectorsRun(r, [&calls] { ++calls; });
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(v.passed);
  EXPECT_EQ(v.text.rfind("wrote ", 0), 0u) << v.text;
  EXPECT_TRUE(fs::exists(out / "vlc.txt"));
  fs::remove_all(out);
}

TEST(CheckVectorsRequest, OneModeOnlyWithCheckAndACheckDirectory) {
  const fs::path d = portWith("request", "x\n", "");
  EXPECT_EQ(requestRefusal("", "", {}), "give exactly one of --out DIR and --check DIR");
  EXPECT_EQ(requestRefusal("out", d.string(), {}), "give exactly one of --out DIR and --check DIR");
  EXPECT_EQ(requestRefusal("out", "", {"vlc"}), "--only selects what --check compares: give --check DIR");
  EXPECT_EQ(requestRefusal("", (d / "vlc.txt").string(), {}),
            "--check " + (d / "vlc.txt").string() + ": not a directory");
  EXPECT_EQ(requestRefusal("", d.string(), {"vlc"}), "");
  // An existing, non-empty --out is refused before any vector is made.
  EXPECT_NE(requestRefusal(d.string(), "", {}).find("exists and is not empty"), std::string::npos);
  fs::remove_all(d);
}

TEST(VectorsVerdict, PassFailAbsentAndNothingSelected) {
  VectorsCheck c;
  c.report = "  vlc.txt: 3 of 3 match (pass)\n";
  c.present = 1;
  c.checked = c.matched = 3;
  EXPECT_TRUE(vectorsVerdict(c, "port", false).passed);
  EXPECT_EQ(vectorsVerdict(c, "port", false).text, "the 1 vector files present in port match\n" + c.report);
  EXPECT_EQ(vectorsVerdict(c, "port", true).text,
            "the 1 vector files present in port match (the 3 entries --only selects)\n" + c.report);
  c.passed = false;
  c.matched = 1;
  EXPECT_FALSE(vectorsVerdict(c, "port", false).passed);
  EXPECT_EQ(vectorsVerdict(c, "port", false).text, "1 of 3 entries match in port:\n" + c.report);
  c.present = 0;
  EXPECT_EQ(vectorsVerdict(c, "port", false).text, "no vector file selected is in port:\n" + c.report);
  c.anySelected = false;
  EXPECT_THROW(vectorsVerdict(c, "port", true), Error);
}

// A test program is installed nowhere: the source tree's samples.
TEST(SampleVectorStreams, TheSourceTreesSamplesFromABuildTree) {
  const std::string samples = std::string(VBIM_SOURCE_DIR) + "/streams/samples/";
  EXPECT_EQ(sampleVectorStreams(),
            (std::vector<std::string>{samples + "day_clear.vbim", samples + "day_weather.vbim"}));
}

TEST(StreamVectors, AStreamThatCannotBeOpenedIsNamedWithItsOption) {
  try {
    streamVectors({"/nonexistent/day.vbim"}, "--stream ", ipu::kDefaultIdct);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--stream /nonexistent/day.vbim: cannot open the stream file");
  }
}

}  // namespace
}  // namespace vbim::runs
