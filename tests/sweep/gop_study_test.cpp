// The GOP study of a sweep plan (docs/gop-study.md): a small variant of examples/sweeps/gop-study.toml
// over a Technique A day cycle authored here gives equal_quality.csv/.md and its figure, with the
// columns the docs name; at equal quality (within the tolerance) the GOP rows need less bitrate than
// the intra-only reference, and only they keep the EE busy. The same bytes at any --jobs. Bad `gops`
// and [equal_quality] entries are refused with file:line: key.
#include <gtest/gtest.h>

#include <unistd.h>
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_CLI, args);
}

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("gop_study_" + name);
}

// CSV fields, with "quoted, fields" kept whole.
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      f.emplace_back();
    } else {
      f.back() += c;
    }
  }
  return f;
}

std::vector<std::map<std::string, std::string>> rows(const std::string& csv, std::vector<std::string>* header) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  *header = fields(line);
  std::vector<std::map<std::string, std::string>> out;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = fields(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < f.size() && i < header->size(); ++i) row[(*header)[i]] = f[i];
    out.push_back(row);
  }
  return out;
}

// The committed study's sections, smaller: 48 frames of 128x128, three quantisers, GOP 12 with and
// without B pictures, 10 s cases and a coarse stall search.
const char* kSmallStudy = R"(
[run]
duration = "10s"

[axes]
streams = ["source.vbim"]
qscales = [7, 8, 9]
gops = [{ gop = 1 }, { gop = 12 }, { gop = 12, b_frames = 2 }]
rings = ["4:8"]

[measures]
include = ["frames_late", "ring_occupancy", "survivable_stall", "coding", "busy_share"]

[stall_search]
stall_at = "3s"
max_stall = "8s"
resolution = "500ms"
settle = "2s"

[equal_quality]
reference_qscale = 8
tolerance_db = 0.3
)";

class GopStudy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch("small"));
    fs::create_directories(*dir_);
    const Result a =
        run("author --procedural --size 128 --cell-size 20 --sky-width 64 --exposure -1 --q 2 --frame-count 48 "
            "--start-hour 0 --end-hour 24 --fps 1 --force --out " +
            (*dir_ / "source.vbim").string());
    ASSERT_EQ(a.status, 0) << a.output;
    std::ofstream(*dir_ / "study.toml") << kSmallStudy;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path* dir_;
};
fs::path* GopStudy::dir_ = nullptr;

TEST_F(GopStudy, EqualQualityRowsNeedLessBitrateThanIntraOnly) {
  const fs::path one = *dir_ / "jobs1", two = *dir_ / "jobs2";
  const Result r2 = run("profile --plan " + (*dir_ / "study.toml").string() + " --jobs 2 --out " + two.string());
  ASSERT_EQ(r2.status, 0) << r2.output;
  for (const char* f : {"cases.csv", "cases.jsonl", "equal_quality.csv", "equal_quality.md",
                        "plots/equal_quality_1.png", "plots/equal_quality_1.svg"})
    EXPECT_TRUE(fs::exists(two / f)) << f;

  std::vector<std::string> header;
  const auto table = rows(vbim::testing::readFileBytes(two / "equal_quality.csv"), &header);
  const std::vector<std::string> expected{"group",
                                          "structure",
                                          "gop",
                                          "b_frames",
                                          "stream",
                                          "qscale",
                                          "psnr_mean_db",
                                          "psnr_min_db",
                                          "psnr_delta_db",
                                          "equal",
                                          "bitrate_kbps",
                                          "bitrate_vs_reference_pct",
                                          "sectors_per_frame",
                                          "ring_banks_mean",
                                          "longest_stall_s",
                                          "stall_saturated",
                                          "ipu_busy_pct",
                                          "ee_busy_pct"};
  EXPECT_EQ(header, expected);
  ASSERT_EQ(table.size(), 3u);  // one row per GOP structure
  const auto& ref = table[0];
  EXPECT_EQ(ref.at("gop"), "1");
  EXPECT_EQ(ref.at("qscale"), "8");
  EXPECT_EQ(ref.at("psnr_delta_db"), "+0.00");
  EXPECT_GT(std::stod(ref.at("psnr_mean_db")), 25.0);
  EXPECT_DOUBLE_EQ(std::stod(ref.at("ee_busy_pct")), 0.0);  // intra only: IDEC, no EE work modelled
  for (std::size_t i = 1; i < table.size(); ++i) {
    const auto& row = table[i];
    SCOPED_TRACE(row.at("structure"));
    EXPECT_EQ(row.at("gop"), "12");
    EXPECT_EQ(row.at("equal"), "yes");
    EXPECT_LE(std::fabs(std::stod(row.at("psnr_delta_db"))), 0.3);
    EXPECT_LT(std::stod(row.at("bitrate_kbps")), std::stod(ref.at("bitrate_kbps")));
    EXPECT_LT(std::stod(row.at("sectors_per_frame")), std::stod(ref.at("sectors_per_frame")));
    EXPECT_GT(std::stod(row.at("ee_busy_pct")), 0.0);
    EXPECT_GT(std::stod(row.at("ipu_busy_pct")), 0.0);
    EXPECT_FALSE(row.at("longest_stall_s").empty());
  }
  EXPECT_EQ(table[2].at("b_frames"), "2");
  const std::string md = vbim::testing::readFileBytes(two / "equal_quality.md");
  EXPECT_NE(md.find("| GOP structure | stream | q | PSNR mean (dB) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| GOP 12, 2 B |"), std::string::npos) << md;

  // Every case carries its coding and busy-share columns.
  std::vector<std::string> caseHeader;
  const auto cases = rows(vbim::testing::readFileBytes(two / "cases.csv"), &caseHeader);
  ASSERT_EQ(cases.size(), 1u + 3u * 3u);  // the source as is, then 3 quantisers x 3 GOP structures
  for (const char* c : {"qscale", "gop", "b_frames", "bitrate_bps", "sectors_per_frame", "psnr_mean_db", "psnr_min_db",
                        "ipu_busy_share", "ee_busy_share"})
    EXPECT_TRUE(cases[0].count(c)) << c;
  EXPECT_EQ(cases[0].at("psnr_mean_db"), "");  // the source itself: nothing to compare with
  EXPECT_EQ(cases[1].at("stream"), "source_q7_g1");
  EXPECT_EQ(cases[3].at("stream"), "source_q7_g12b2");

  const Result r1 = run("profile --plan " + (*dir_ / "study.toml").string() + " --jobs 1 --out " + one.string());
  ASSERT_EQ(r1.status, 0) << r1.output;
  for (const char* f : {"cases.csv", "cases.jsonl", "equal_quality.csv", "equal_quality.md"})
    EXPECT_TRUE(vbim::testing::readFileBytes(one / f) == vbim::testing::readFileBytes(two / f))
        << f << " differs between --jobs 1 and 2";
}

TEST_F(GopStudy, BadGopsAndEqualQualityNameFileLineAndKey) {
  const fs::path plan = *dir_ / "bad.toml";
  const std::string axes = "[axes]\nstreams = [\"source.vbim\"]\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {axes + "qscales = [8]\ngops = [{ gop = 2000 }]\n", "bad.toml:4: key 'axes.gops.gop': 2000 is outside [1, 1024]"},
      {axes + "qscales = [8]\ngops = [{ gop = 3, b_frames = 3 }]\n", "bad.toml:4: key 'axes.gops.b_frames'"},
      {axes + "qscales = [8]\ngops = [{ gop = 12, open_gop = true }]\n", "bad.toml:4: key 'axes.gops.open_gop'"},
      {axes + "qscales = [8]\ngops = [{ gop = 12, b = 2 }]\n", "bad.toml:4: key 'axes.gops.b': unknown key"},
      {axes + "qscales = [8]\ngops = [12]\n", "bad.toml:4: key 'axes.gops': expected GOP structures as tables"},
      {axes + "qscales = [8]\ngops = [{ gop = 6 }, { gop = 6 }]\n", "bad.toml:4: key 'axes.gops': gop 6"},
      {axes + "gops = [{ gop = 6 }]\n", "bad.toml:3: key 'axes.gops': needs qscales or bitrates"},
      {axes + "qscales = [8]\ngops = [{ gop = 1 }]\n[measures]\ninclude = [\"coding\"]\n[equal_quality]\n"
              "reference_qscale = 6\n",
       "bad.toml:8: key 'equal_quality.reference_qscale': no re-encode is the reference"},
      {axes + "qscales = [8]\ngops = [{ gop = 1 }]\n[equal_quality]\nreference_qscale = 8\n",
       "key 'equal_quality.reference_qscale': needs the PSNR of each re-encode: add \"coding\""},
      {axes + "qscales = [8]\ngops = [{ gop = 1 }]\n[measures]\ninclude = [\"coding\"]\n[equal_quality]\n"
              "reference_qscale = 8\ntolerance_db = 0\n",
       "bad.toml:9: key 'equal_quality.tolerance_db'"},
  };
  for (const Case& c : cases) {
    std::ofstream(plan, std::ios::trunc) << c.text;
    const Result r = run("profile --plan " + plan.string() + " --out " + (*dir_ / "bad-out").string());
    EXPECT_NE(r.status, 0) << c.text;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.text << "\n" << r.output;
    EXPECT_FALSE(fs::exists(*dir_ / "bad-out"));
  }
}

}  // namespace
