// sweep/outputs/plan_modes: what `vbim profile --plan` warns of in a plan's records (failed cases,
// at most five named; stuck and starved runs counted), and one shard's cases.
#include "sweep/outputs/plan_modes.hpp"

#include <gtest/gtest.h>

#include "player/report.hpp"

namespace {

using namespace vbim;
using sweep::CaseRecord;

CaseRecord failed(std::size_t number) {
  CaseRecord r;
  r.number = number;
  r.ok = false;
  r.error = "bad case " + std::to_string(number);
  return r;
}

// A run whose display stopped for its last `seconds` (player::runHealth), after `shown` frames.
CaseRecord behind(std::size_t number, std::int64_t shown, double seconds) {
  CaseRecord r;
  r.number = number;
  r.result.lightmap.framesShown = shown;
  r.result.totals.endsBehind = true;
  r.result.totals.lastProgressAt = 0;
  r.result.totals.lastVsyncAt = fromMs(static_cast<std::int64_t>(seconds * 1000));
  return r;
}

TEST(PlanModes, NoWarningsForHealthyCases) {
  EXPECT_TRUE(sweep::caseWarnings({CaseRecord{}, CaseRecord{}}).empty());
}

TEST(PlanModes, FiveFailuresAreNamedAndTheRestCounted) {
  std::vector<CaseRecord> records;
  for (std::size_t i = 0; i < 7; ++i) records.push_back(failed(i));
  const std::vector<std::string> w = sweep::caseWarnings(records);
  ASSERT_EQ(w.size(), 6u);
  EXPECT_EQ(w[0], "case 0 failed: bad case 0");
  EXPECT_EQ(w[4], "case 4 failed: bad case 4");
  EXPECT_EQ(w[5], "... and 2 more failed cases (see the table)");
}

TEST(PlanModes, StuckAndStarvedRunsAreCountedOnce) {
  const double longStall = toSeconds(player::kStuckAfter) + 1;
  const std::vector<std::string> w =
      sweep::caseWarnings({behind(0, 3, longStall), behind(1, 0, longStall), behind(2, 5, 0.5), failed(3)});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "case 3 failed: bad case 3");
  EXPECT_EQ(w[1].rfind("warning: 1 stuck and 1 starved of 4 cases:", 0), 0u) << w[1];
}

TEST(PlanModes, AShardHoldsItsBlockOfCases) {
  sweep::LoadedPlan p;
  for (std::size_t i = 0; i < 10; ++i) {
    sweep::PlanCase c;
    c.number = i;
    p.cases.push_back(c);
  }
  const sweep::Shard s = sweep::selectShard(p, "2/3");
  EXPECT_EQ(s.name, "shard-2-of-3");
  EXPECT_EQ(s.cases.size(), s.last - s.first);
  ASSERT_FALSE(s.cases.empty());
  EXPECT_EQ(s.cases.front().number, s.first);
  EXPECT_THROW(sweep::selectShard(p, "4/3"), Error);
}

}  // namespace
