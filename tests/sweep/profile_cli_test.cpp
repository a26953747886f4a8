// `vbim profile` end to end on the committed sample: the outputs exist and are complete, a second
// run gives the same bytes (CSV, JSON, PNG, SVG), the survivable stall grows with the ring, and bad input
// exits non-zero with a message naming what was wrong, leaving no output directory behind.
#include <gtest/gtest.h>

#include <unistd.h>
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

using Result = vbim::testing::CommandResult;

Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_CLI, args);
}

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("profile_" + name);
}

const std::string kSmall = " --ring 4:8,4:64 --duration 8s --max-stall 12s --resolution 250ms --settle 4s";

// Reads longest_stall_s of (bufmax, policy, criterion) from stall.csv.
double longest(const std::string& csv, const std::string& bufmax, const std::string& policy, const std::string& crit) {
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
    if (f.size() >= 8 && f[2] == bufmax && f[3] == policy && f[4] == crit) return f[7].empty() ? -1 : std::stod(f[7]);
  }
  return -2;
}

TEST(ProfileCli, WritesTablesAndPlotsDeterministically) {
  const fs::path a = scratch("a"), b = scratch("b");
  const Result ra = run("profile " + kSample + kSmall + " --policy blend-through,hard-skip --out " + a.string());
  ASSERT_EQ(ra.status, 0) << ra.output;
  const Result rb = run("profile " + kSample + kSmall + " --policy blend-through,hard-skip --out " + b.string());
  ASSERT_EQ(rb.status, 0) << rb.output;
  for (const char* f :
       {"sweep.csv", "stall.csv", "profile.json", "plots/survivable_stall.png", "plots/survivable_stall.svg",
        "plots/occupancy_day_clear_none_blend-through.png", "plots/occupancy_day_clear_none_blend-through.svg",
        "plots/lag_pop_day_clear_none_hard-skip.png", "plots/lag_pop_day_clear_none_hard-skip.svg"}) {
    ASSERT_TRUE(fs::exists(a / f)) << f << "\n" << ra.output;
    EXPECT_GT(fs::file_size(a / f), 100u) << f;
    EXPECT_EQ(vbim::testing::readFileBytes(a / f), vbim::testing::readFileBytes(b / f))
        << f << " differs between two identical runs";
  }
  // 2 rings x 2 policies x 1 fault plan; 2 rings x 2 policies x 2 criteria.
  const std::string sweep = vbim::testing::readFileBytes(a / "sweep.csv"),
                    stall = vbim::testing::readFileBytes(a / "stall.csv");
  EXPECT_EQ(std::count(sweep.begin(), sweep.end(), '\n'), 1 + 4);
  EXPECT_EQ(std::count(stall.begin(), stall.end(), '\n'), 1 + 8);
  EXPECT_NE(ra.output.find("Open:"), std::string::npos);
  // The survivable stall grows with the ring; blend-through hides the stall (no pop above normal
  // playback's, saturated at --max-stall), hard-skip snaps: a pop.
  const double small = longest(stall, "8", "blend-through", "no-late-frame");
  const double large = longest(stall, "64", "blend-through", "no-late-frame");
  EXPECT_GT(small, 0.5) << stall;  // the EE buffers bridge some stall even with an 8-sector ring
  EXPECT_GT(large, small) << stall;
  EXPECT_GE(longest(stall, "8", "blend-through", "pop"), 12.0) << stall;
  EXPECT_LT(longest(stall, "8", "hard-skip", "pop"), 12.0) << stall;

  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(ProfileCli, BadInputExitsNonZeroAndLeavesNothing) {
  const fs::path out = scratch("bad");
  struct Case {
    std::string args, expect;
  } cases[] = {
      {"profile /nonexistent.vbim --out " + out.string(), "nonexistent.vbim"},
      {"profile " + kSample + " --ring 4x8 --out " + out.string(), "--ring '4x8'"},
      {"profile " + kSample + " --ring 0:8 --out " + out.string(), "--ring '0:8'"},
      {"profile " + kSample + " --policy fast --out " + out.string(), "--policy 'fast'"},
      {"profile " + kSample + " --pop-threshold lots --out " + out.string(), "--pop-threshold 'lots'"},
      {"profile " + kSample + " --max-stall 0s --out " + out.string(), "must be positive"},
      {"profile " + kSample + " --faults /nonexistent.toml --out " + out.string(), "nonexistent.toml"},
      {"profile " + std::string(VBIM_SOURCE_DIR) + "/README.md --out " + out.string(), "README.md"},
  };
  for (const Case& c : cases) {
    const Result r = run(c.args);
    EXPECT_NE(r.status, 0) << c.args;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  // A non-empty output directory without --force.
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "x";
  const Result r = run("profile " + kSample + " --ring 4:8 --no-search --duration 2s --out " + out.string());
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(fs::exists(out / "keep.txt"));
  EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("sweep "), std::string::npos) << "refused only after running the sweep:\n" << r.output;
  fs::remove_all(out);
}

}  // namespace
