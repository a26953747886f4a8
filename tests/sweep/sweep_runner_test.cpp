// player::profile::runPlanCases: cases run on several host threads give the same records as on
// one (each case has its own stream handle and player; nothing is shared but read-only inputs), in
// case order; a case that throws becomes a failed record and the others still run. Also run under
// ThreadSanitizer by .ci/run.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>

#include "sweep/runner.hpp"

namespace {

using namespace vbim;
using namespace vbim::sweep;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

SweepPlanSpec smallPlan() {
  SweepPlanSpec p;
  p.streams = {{"day_clear", kSample, 0, 0}, {"missing", "/nonexistent/stream.vbim", 0, 0}};
  p.platforms = {PlatformVariant{}};
  FaultTemplate t{"stall", {}};
  for (int d = 0; d < 3; ++d) {
    iop::Fault f;
    f.kind = iop::Fault::Kind::Stall;
    f.at = fromMs(1000 + 300 * d);
    f.duration = fromMs(600 + 900 * d);
    FaultDraw draw;
    draw.plan.faults.push_back(f);
    t.draws.push_back(draw);
  }
  p.faults = {t};
  p.policies = {"blend-through"};
  p.rings = {RingSize{4, 8}, RingSize{4, 32}};
  p.seeds = {5};
  p.duration = fromMs(4000);
  p.measures = {Measure::FramesLate, Measure::PopMax, Measure::LagMax, Measure::RingOccupancy};
  return p;
}

std::vector<CaseRecord> runAll(const SweepPlanSpec& plan, unsigned jobs, std::size_t* reported) {
  const std::vector<PlanCase> cases = expandPlan(plan);
  RunOptions o;
  o.jobs = jobs;
  return runPlanCases(
      plan, cases, [&](std::size_t s) { return bareStream(plan.streams[s].path); }, o,
      [&](const CaseRecord&) { ++*reported; });
}

TEST(SweepRunner, ThreadsGiveTheSameRecordsInCaseOrder) {
  const SweepPlanSpec plan = smallPlan();
  std::size_t reported1 = 0, reported3 = 0;
  const std::vector<CaseRecord> one = runAll(plan, 1, &reported1);
  const std::vector<CaseRecord> three = runAll(plan, 3, &reported3);
  ASSERT_EQ(one.size(), 12u);  // 2 streams x 2 rings x 3 draws
  EXPECT_EQ(reported1, 12u);
  EXPECT_EQ(reported3, 12u);
  for (std::size_t i = 0; i < one.size(); ++i) {
    const CaseRecord &a = one[i], &b = three[i];
    EXPECT_EQ(a.number, i);
    EXPECT_EQ(b.number, i);
    EXPECT_EQ(a.ok, b.ok) << i;
    EXPECT_EQ(a.error, b.error) << i;
    EXPECT_EQ(a.result.lightmap.framesLate, b.result.lightmap.framesLate) << i;
    EXPECT_EQ(a.result.lightmap.framesShown, b.result.lightmap.framesShown) << i;
    EXPECT_EQ(a.result.pop.value, b.result.pop.value) << i;
    EXPECT_EQ(a.result.pop.at, b.result.pop.at) << i;
    EXPECT_EQ(a.result.totals.lag.value, b.result.totals.lag.value) << i;
    EXPECT_EQ(a.result.totals.ringSum, b.result.totals.ringSum) << i;
    EXPECT_EQ(a.result.ringUnderruns, b.result.ringUnderruns) << i;
  }
  // The first stream's cases ran; the missing file's failed with the reason, not the sweep.
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_TRUE(one[i].ok) << one[i].error;
    EXPECT_GT(one[i].result.lightmap.framesShown, 0) << i;
  }
  for (std::size_t i = 6; i < 12; ++i) {
    EXPECT_FALSE(one[i].ok);
    EXPECT_NE(one[i].error.find("nonexistent"), std::string::npos) << one[i].error;
  }
  // A longer stall with the small ring shows in the records: the draws are not all alike.
  EXPECT_NE(one[0].result.totals.ringSum, one[2].result.totals.ringSum);
}

// Ctrl-C during `vbim profile --plan --jobs 2` ended the process in std::terminate (exit 134): the
// progress report that saw it threw on a worker thread. An exception out of the report now stops the
// sweep (no case starts after it, none is reported after it) and reaches the caller, which exits 130.
TEST(SweepRunner, AnExceptionFromTheReportStopsTheSweepAndReachesTheCaller) {
  struct Interrupted : std::runtime_error {
    Interrupted() : std::runtime_error("interrupted") {}
  };
  const SweepPlanSpec plan = smallPlan();
  const std::vector<PlanCase> cases = expandPlan(plan);
  for (const unsigned jobs : {1u, 2u, 3u}) {
    std::atomic<int> opened{0};
    int reported = 0;
    RunOptions o;
    o.jobs = jobs;
    EXPECT_THROW(runPlanCases(
                     plan, cases,
                     [&](std::size_t s) {
                       ++opened;
                       return bareStream(plan.streams[s].path);
                     },
                     o,
                     [&](const CaseRecord&) {
                       if (++reported == 2) throw Interrupted();
                     }),
                 Interrupted)
        << jobs << " jobs";
    EXPECT_EQ(reported, 2) << jobs << " jobs";
    // Only the cases already under way on the other threads ran after the report that threw.
    EXPECT_LE(opened.load(), 2 + static_cast<int>(jobs) - 1) << jobs << " jobs";
  }
}

TEST(SweepRunner, ShardRangesCoverEveryCaseOnce) {
  for (std::size_t cases : {1u, 7u, 64u, 1000u}) {
    for (std::size_t n = 1; n <= std::min<std::size_t>(cases, 9); ++n) {
      std::size_t next = 0;
      for (std::size_t k = 1; k <= n; ++k) {
        const auto [first, last] = shardRange(cases, k, n);
        EXPECT_EQ(first, next);
        EXPECT_GE(last - first, cases / n);
        EXPECT_LE(last - first, cases / n + 1);
        next = last;
      }
      EXPECT_EQ(next, cases);
    }
  }
}

}  // namespace
