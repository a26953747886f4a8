// What `vbim profile` says of each sweep run and stall search (runs/profile_run.hpp): the line, the
// STUCK or STARVED flag and the warning of a run whose display stopped, and a stall search's longest
// survived stall, at the maximum or not found at all.
#include "runs/profile_run.hpp"

#include <gtest/gtest.h>

#include "player/report.hpp"

namespace vbim::runs {
namespace {

sweep::SweepRun run(std::int64_t shown, double secondsBehind) {
  sweep::SweepRun r;
  r.stream = "day";
  r.ring = {4, 16};
  r.faults = "stall";
  r.policy = "blend-through";
  r.result.lightmap.framesShown = shown;
  r.result.lightmap.framesLate = 2;
  r.result.pop.value = 7;
  r.result.totals.lag.value = 3;
  r.result.totals.endsBehind = secondsBehind > 0;
  r.result.totals.lastProgressAt = 0;
  r.result.totals.lastVsyncAt = fromMs(static_cast<std::int64_t>(secondsBehind * 1000));
  return r;
}

TEST(ProfileRunLines, AHealthyRunIsOneLineWithoutAWarning) {
  const SweepRunReport r = sweepRunReport(run(10, 0));
  EXPECT_EQ(r.line, "sweep  day  ring 4:16  faults stall  blend-through: late 2, pop max 7, lag max 3");
  EXPECT_TRUE(r.warning.empty());
}

TEST(ProfileRunLines, ARunWhoseDisplayStoppedIsFlaggedAndWarnedOf) {
  const double stopped = toSeconds(player::kStuckAfter) + 1;
  const SweepRunReport stuck = sweepRunReport(run(3, stopped));
  EXPECT_EQ(stuck.line.substr(stuck.line.size() - 7), "  STUCK");
  EXPECT_EQ(stuck.warning.rfind("day ring 4:16 blend-through: ", 0), 0u) << stuck.warning;
  const SweepRunReport starved = sweepRunReport(run(0, stopped));
  EXPECT_EQ(starved.line.substr(starved.line.size() - 9), "  STARVED");
  EXPECT_FALSE(starved.warning.empty());
}

TEST(ProfileRunLines, AStallSearchSaysItsLongestStall) {
  sweep::StallRow row;
  row.stream = "day";
  row.ring = {5, 160};
  row.policy = "hard-skip";
  row.result.longest = fromMs(2500);
  row.result.runs = 9;
  EXPECT_EQ(stallSearchLine(row), "stall  day  ring 5:160  hard-skip  no-late-frame: 2.500 s (9 runs)");
  row.result.saturated = true;
  EXPECT_EQ(stallSearchLine(row), "stall  day  ring 5:160  hard-skip  no-late-frame: >= 2.500 s (9 runs)");
  row.result.longest.reset();
  EXPECT_EQ(stallSearchLine(row), "stall  day  ring 5:160  hard-skip  no-late-frame: fails without a stall (9 runs)");
}

}  // namespace
}  // namespace vbim::runs
