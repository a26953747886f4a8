// vbim replay explains a schedule (docs/porting.md, "Replay"): with frames 5-8 of play's arrivals
// delayed by 250 vsyncs it lists the late and unshown arrivals, writes timeline.csv, and --compare
// names the first vsync that differs from play's run with the frame due, the target and lateness;
// --json says the same as one document on stdout (docs/cli.md, "JSON summaries").
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

// From the source tree: the tests name the samples by their paths in it.
Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_BINARY, args, VBIM_SOURCE_DIR);
}

const std::string kStream = "streams/samples/day_clear.vbim";

class Replay : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = vbim::testing::testScratchDir("replay_test");
    const Result p = run("play " + kStream + " --duration 20s --no-trace --out " + (dir_ / "play").string());
    ASSERT_EQ(p.status, 0) << p.output;
  }
  void TearDown() override { fs::remove_all(dir_); }
  // play's arrivals.csv with the vsync of frames `from`..`to` (both streams) moved by `by`.
  fs::path delayed(std::int64_t from, std::int64_t to, std::int64_t by) {
    std::ifstream in(dir_ / "play/arrivals.csv");
    std::ofstream out(dir_ / "delayed.csv");
    std::string line;
    while (std::getline(in, line)) {
      const auto c1 = line.find(',');
      const auto c2 = line.find(',', c1 + 1);
      const std::string frame = line.substr(c2 + 1);
      if (line.find(":0,") != std::string::npos && !frame.empty()) {
        const std::int64_t f = std::stoll(frame);
        if (f >= from && f <= to) line = std::to_string(std::stoll(line.substr(0, c1)) + by) + line.substr(c1);
      }
      out << line << "\n";
    }
    return dir_ / "delayed.csv";
  }
  fs::path dir_;
};

// `vbim args` (from the source tree) with stdout into `out`: the result holds stderr alone.
Result runToFile(const std::string& args, const fs::path& out) {
  return vbim::testing::runCommand("cd '" + std::string(VBIM_SOURCE_DIR) + "' && { " + VBIM_BINARY + " " + args +
                                   " > '" + out.string() + "'; }");
}

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST_F(Replay, FramesDelayedBy250VsyncsAreShownLateAndTheFirstDifferenceIsNamed) {
  const fs::path log = delayed(5, 8, 250);
  const Result r = run("replay " + kStream + " --arrivals " + log.string() + " --compare " + (dir_ / "play").string() +
                       " --out " + (dir_ / "replay").string());
  EXPECT_EQ(r.status, 1) << r.output;
  // Frame 5 of day_clear (1 frame a game second, frame 0 due at 0.5 s) is due at vsync 330: there
  // play starts blending toward it, the delayed replay still shows frame 4.
  EXPECT_NE(r.output.find("first difference at vsync 330 (5.505500 s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lightmap: frame 5 due, target frame 4"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("behind: frame 5 arrives at vsync 521"), std::string::npos) << r.output;
  // Every delayed arrival is listed with its line and lateness; 6-8 come after frame 9 was due.
  for (int f = 5; f <= 8; ++f) {
    const std::string due = std::to_string(330 + 60 * (f - 5));
    EXPECT_NE(r.output.find("lightmap:0 frame " + std::to_string(f) + " arrived at vsync " +
                            std::to_string(521 + 60 * (f - 5)) + ", due at vsync " + due + ": 191 vsyncs late"),
              std::string::npos)
        << f << r.output;
  }
  EXPECT_NE(r.output.find("frame 6 arrived at vsync 581, due at vsync 390: 191 vsyncs late; never shown"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("8 arrival(s) late or never shown"), std::string::npos) << r.output;
  // Output is complete even though it differs: hashes.txt and timeline.csv, a row per vsync.
  const std::vector<std::string> hashes = lines(dir_ / "replay/hashes.txt");
  const std::vector<std::string> timeline = lines(dir_ / "replay/timeline.csv");
  ASSERT_EQ(timeline.size(), hashes.size() + 1);
  EXPECT_EQ(timeline.front().rfind("vsync,time_s,hash,due_seq,target_seq,variant,fix,pop,behind,catch_up,snapped", 0),
            0u);
  // At vsync 521 frame 5 arrives and becomes the target, late by 191 vsyncs (catch_up = 1).
  EXPECT_EQ(timeline[522].rfind("521,", 0), 0u);
  std::istringstream row(timeline[522]);
  std::vector<std::string> f;
  for (std::string c; std::getline(row, c, ',');) f.push_back(c);
  ASSERT_EQ(f.size(), 19u) << timeline[522];
  EXPECT_EQ(f[3], "8");     // due_seq
  EXPECT_EQ(f[4], "5");     // target_seq
  EXPECT_EQ(f[9], "1");     // catch_up
  EXPECT_EQ(f[14], "521");  // target_arrived_vsync
  EXPECT_EQ(f[15], "330");  // target_due_vsync
  EXPECT_EQ(f[16], "191");  // target_late_vsyncs
  EXPECT_EQ(hashes[521].substr(0, 4), "521 ");
}

TEST_F(Replay, CompareAcceptsARunDirectoryOrAHashesFileAndExitsZeroWhenEqual) {
  const std::string log = (dir_ / "play/arrivals.csv").string();
  const Result dir = run("replay " + kStream + " --arrivals " + log + " --compare " + (dir_ / "play").string() +
                         " --out " + (dir_ / "a").string());
  EXPECT_EQ(dir.status, 0) << dir.output;
  EXPECT_NE(dir.output.find("every hash equals"), std::string::npos) << dir.output;
  EXPECT_NE(dir.output.find("0 arrival(s) late or never shown"), std::string::npos) << dir.output;
  // A port's hashes.txt: its own times are not compared; one wrong hash is named with its line.
  std::vector<std::string> h = lines(dir_ / "play/hashes.txt");
  {
    std::ofstream port(dir_ / "port.txt");
    for (std::size_t i = 0; i < h.size(); ++i) {
      std::string l = h[i];
      l = l.substr(0, l.find(' ')) + " 9.9 " + l.substr(l.rfind(' ') + 1);
      if (i == 700) l.back() = l.back() == '0' ? '1' : '0';
      port << l << "\n";
    }
  }
  const Result port = run("replay " + kStream + " --arrivals " + log + " --compare " + (dir_ / "port.txt").string() +
                          " --out " + (dir_ / "b").string());
  EXPECT_EQ(port.status, 1) << port.output;
  EXPECT_NE(port.output.find("first difference at vsync 700"), std::string::npos) << port.output;
  EXPECT_NE(port.output.find("port.txt:701 "), std::string::npos) << port.output;
  EXPECT_NE(port.output.find("lightmap: frame 11 due, target frame 11"), std::string::npos) << port.output;
  // A malformed compare file is refused before anything is written.
  std::ofstream(dir_ / "bad.txt") << "0 0.0 0123456789abcdef\n2 0.1 0123456789abcdef\n";
  const Result bad = run("replay " + kStream + " --arrivals " + log + " --compare " + (dir_ / "bad.txt").string() +
                         " --out " + (dir_ / "c").string());
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.txt:2: vsync '2' where vsync 1 belongs"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir_ / "c"));
}

TEST_F(Replay, MalformedLogsAreRefusedOrWarnedWithTheirLine) {
  const std::vector<std::string> a = lines(dir_ / "play/arrivals.csv");
  std::string text;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) text += a[i] + "\n";
  text += a[5] + "\n" + a.back() + "\n";  // line 6's frame again, before the end row
  std::ofstream(dir_ / "twice.csv") << text;
  const Result twice =
      run("replay " + kStream + " --arrivals " + (dir_ / "twice.csv").string() + " --out " + (dir_ / "t").string());
  EXPECT_EQ(twice.status, 2) << twice.output;
  EXPECT_NE(twice.output.find("twice.csv:" + std::to_string(a.size()) + ": " + a[5].substr(a[5].find(',') + 1, 10)),
            std::string::npos)
      << twice.output;
  EXPECT_NE(twice.output.find("arrives twice (first at line 6"), std::string::npos) << twice.output;
  EXPECT_FALSE(fs::exists(dir_ / "t"));
  // A gap is replayed, with a warning naming the line where the log goes on.
  text.clear();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != "271,lightmap:0,5") text += a[i] + "\n";
  }
  std::ofstream(dir_ / "gap.csv") << text;
  const Result gap =
      run("replay " + kStream + " --arrivals " + (dir_ / "gap.csv").string() + " --out " + (dir_ / "g").string());
  EXPECT_EQ(gap.status, 0) << gap.output;
  // Named by the command, as every warning of vbim is, then the file and line.
  EXPECT_NE(gap.output.find("vbim replay: warning: " + (dir_ / "gap.csv").string() + ":"), std::string::npos)
      << gap.output;
  EXPECT_NE(gap.output.find("lightmap frame 5 never arrives (the log goes on at frame 6)"), std::string::npos)
      << gap.output;
}

// The document holds what the text report says: the same late and unshown arrivals, each with its
// line, due vsync and lateness, and the first difference with both hashes and what the presenters
// showed; it is printed before the exit 1 of a difference.
TEST_F(Replay, JsonSaysWhatTheReportSays) {
  const fs::path log = delayed(5, 8, 250);
  const std::string args =
      "replay " + kStream + " --arrivals " + log.string() + " --compare " + (dir_ / "play").string() + " --every 300 ";
  const Result text = run(args + "--out " + (dir_ / "text").string());
  ASSERT_EQ(text.status, 1) << text.output;
  const Result r = runToFile(args + "--json --out " + (dir_ / "json").string(), dir_ / "replay.json");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("vbim replay: the replay differs from " + (dir_ / "play" / "hashes.txt").string()),
            std::string::npos)
      << r.output;
  const nlohmann::json j = nlohmann::json::parse(vbim::testing::readFileBytes(dir_ / "replay.json"));
  EXPECT_EQ(j["stream"]["path"], kStream);
  EXPECT_EQ(j["stream"]["file"], nullptr);
  EXPECT_EQ(j["arrivals"]["path"], log.string());
  EXPECT_EQ(j["arrivals"]["rows"], lines(log).size() - 2);  // less the header and the end row
  EXPECT_EQ(j["policy"], "blend-through");
  const std::vector<std::string> hashes = lines(dir_ / "json/hashes.txt");
  EXPECT_EQ(j["vsyncs"], hashes.size());
  EXPECT_EQ(j["arrivals"]["end_row_vsyncs"], hashes.size());
  EXPECT_EQ(j["missing_pictures"], 0);
  EXPECT_FALSE(j["arrivals"]["warnings"].empty());
  for (const auto& w : j["arrivals"]["warnings"]) {
    EXPECT_NE(r.output.find("warning: " + w.get<std::string>()), std::string::npos) << w;
  }
  // Both streams' frames 5-8: the text's count, and each line as the text says it.
  const auto& late = j["late_or_unshown"];
  ASSERT_EQ(late.size(), 8u) << late.dump(2);
  EXPECT_NE(text.output.find("8 arrival(s) late or never shown"), std::string::npos) << text.output;
  for (const auto& a : late) {
    const std::int64_t f = a["frame"].get<std::int64_t>();
    EXPECT_EQ(a["arrived_vsync"], 521 + 60 * (f - 5)) << a;
    EXPECT_EQ(a["due_vsync"], 330 + 60 * (f - 5)) << a;
    EXPECT_EQ(a["late_vsyncs"], 191) << a;
    EXPECT_EQ(a["never_shown"], f > 5) << a;
    const std::string said = log.string() + ":" + std::to_string(a["line"].get<int>()) + ": " +
                             a["stream"].get<std::string>() + ":0 frame " + std::to_string(f) + " arrived at vsync " +
                             std::to_string(a["arrived_vsync"].get<int>()) + ", due at vsync " +
                             std::to_string(a["due_vsync"].get<int>()) + ": 191 vsyncs late";
    EXPECT_NE(text.output.find(said), std::string::npos) << said << "\n" << text.output;
  }
  const auto& c = j["compare"];
  EXPECT_EQ(c["with"], (dir_ / "play" / "hashes.txt").string());
  EXPECT_EQ(c["equal"], false);
  EXPECT_EQ(c["vsyncs_compared"], hashes.size());
  const auto& d = c["first_difference"];
  EXPECT_EQ(d["vsync"], 330);
  EXPECT_DOUBLE_EQ(d["time_s"].get<double>(), 5.5055);
  EXPECT_EQ(d["expected_line"], 331);
  EXPECT_EQ(hashes[330], "330 5.505500 " + d["replay_hash"].get<std::string>());
  EXPECT_EQ(lines(dir_ / "play/hashes.txt")[330], "330 5.505500 " + d["expected_hash"].get<std::string>());
  EXPECT_EQ(d["lightmap"]["due_frame"], 5);
  EXPECT_EQ(d["lightmap"]["target_frame"], 4);
  EXPECT_EQ(d["lightmap"]["behind"], true);
  EXPECT_EQ(d["lightmap"]["due_frame_arrives_vsync"], 521);
  EXPECT_EQ(d["lightmap"]["target_late_vsyncs"], 0);
  EXPECT_NE(text.output.find("lightmap: frame 5 due, target frame 4"), std::string::npos) << text.output;
  // Pictures every 300 vsyncs, lightmap and sky: as many as the frames directory holds.
  std::size_t pictures = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_ / "json/frames")) ++pictures;
  EXPECT_EQ(j["output"]["images_written"], pictures);
  EXPECT_EQ(j["output"]["directory"], (dir_ / "json").string());
}

TEST_F(Replay, JsonOfAnEqualReplayOfANameThatIsNotUtf8AndOfALogThatIsRefused) {
  const std::string log = (dir_ / "play/arrivals.csv").string();
  const Result r = runToFile("replay " + kStream + " --arrivals " + log + " --compare " + (dir_ / "play").string() +
                                 " --json -q --out " + (dir_ / "a").string(),
                             dir_ / "a.json");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "");  // -q: no warnings here, and the document is on stdout
  const nlohmann::json j = nlohmann::json::parse(vbim::testing::readFileBytes(dir_ / "a.json"));
  EXPECT_EQ(j["late_or_unshown"], nlohmann::json::array());
  EXPECT_EQ(j["compare"]["equal"], true);
  EXPECT_EQ(j["compare"]["first_difference"], nullptr);
  EXPECT_EQ(j["output"]["images_written"], 0);
  // A log whose name is not UTF-8: its bytes become U+FFFD, and stderr says so.
  const fs::path odd = dir_ / std::string("arrivals\xff.csv");
  fs::copy_file(log, odd);
  const Result o =
      runToFile("replay " + kStream + " --arrivals '" + odd.string() + "' --json --out " + (dir_ / "o").string(),
                dir_ / "o.json");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("vbim replay: warning: text from the input is not UTF-8"), std::string::npos) << o.output;
  EXPECT_NE(
      nlohmann::json::parse(vbim::testing::readFileBytes(dir_ / "o.json"))["arrivals"]["path"].get<std::string>().find(
          "arrivals\xef\xbf\xbd.csv"),
      std::string::npos);
  // A log refused as bad input: exit 2, its message, nothing on stdout and nothing written.
  std::ofstream(dir_ / "bad.csv") << "vsync,stream,frame\n0,lightmap:0,x\n";
  const Result bad = runToFile(
      "replay " + kStream + " --arrivals " + (dir_ / "bad.csv").string() + " --json --out " + (dir_ / "b").string(),
      dir_ / "b.json");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.csv:2:"), std::string::npos) << bad.output;
  EXPECT_EQ(vbim::testing::readFileBytes(dir_ / "b.json"), "");
  EXPECT_FALSE(fs::exists(dir_ / "b"));
}

}  // namespace
