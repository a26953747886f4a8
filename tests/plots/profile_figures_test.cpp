// The profile's figures keep their content: panels, titles, axes, one line per run or per stall
// line, thresholds and limits; writeProfileFigures names its files as `vbim profile` always has.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "plots/profile_figures.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vbim::plots;
using namespace vbim::plots::profile;

std::vector<TracePoint> trace(int banks) {
  return {{0.0, 0, 0, 0}, {0.5, banks, 3, 20}, {1.0, banks - 1, 1, 4}};
}

TEST(ProfileFigures, OccupancyIsPercentOfTheRingOneStepLinePerRun) {
  const Figure f = occupancyFigure("t", {{"ring 8", 4, trace(4)}, {"ring 160", 5, trace(5)}});
  EXPECT_EQ(f.title, "t");
  ASSERT_EQ(f.panels.size(), 1u);
  const Panel& p = f.panels[0];
  EXPECT_EQ(p.title, "Stream ring occupancy");
  EXPECT_EQ(p.yLabel, "% of the ring readable");
  EXPECT_EQ(p.xLabel, "simulated time (s)");
  EXPECT_EQ(p.yMax, 105);
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[1].name, "ring 160");
  EXPECT_TRUE(p.series[0].step);
  EXPECT_EQ(p.series[0].y, (std::vector<double>{0, 100, 75}));
  EXPECT_EQ(p.series[1].y, (std::vector<double>{0, 100, 80}));
  EXPECT_EQ(p.series[0].color, paletteColor(0));
  EXPECT_EQ(p.series[1].color, paletteColor(1));
}

TEST(ProfileFigures, LagPopHasTwoPanelsAndAThresholdOnlyWhenFixed) {
  const std::vector<RunTrace> runs{{"demo", 5, trace(5)}};
  const Figure f = lagPopFigure("t", runs, 40);
  ASSERT_EQ(f.panels.size(), 2u);
  EXPECT_EQ(f.panels[0].title, "Lag: largest per-byte difference from the fault-free run");
  EXPECT_EQ(f.panels[1].title, "Pop: largest per-byte change of the lightmap in one vsync");
  EXPECT_EQ(f.panels[0].series[0].y, (std::vector<double>{0, 3, 1}));
  EXPECT_EQ(f.panels[1].series[0].y, (std::vector<double>{0, 20, 4}));
  ASSERT_EQ(f.panels[1].refLines.size(), 1u);
  EXPECT_EQ(f.panels[1].refLines[0].name, "threshold 40");
  EXPECT_TRUE(lagPopFigure("t", runs, -1).panels[1].refLines.empty());
}

// The run's drive faults are shaded in every panel of the occupancy and lag/pop figures, each kind
// in its own colour and named for what it is (issue #33).
TEST(ProfileFigures, FaultsAreShadedInEveryTimePanelWithTheirNames) {
  const std::vector<RunTrace> runs{{"demo", 5, trace(5)}};
  const std::vector<FaultInterval> faults{{"stall", 0.2, 6.2}, {"read error", 7.0, 7.5}, {"contention", 8, 9}};
  const Figure occ = occupancyFigure("t", runs, faults);
  const Figure lp = lagPopFigure("t", runs, -1, faults);
  for (const Panel* p : {&occ.panels[0], &lp.panels[0], &lp.panels[1]}) {
    ASSERT_EQ(p->bands.size(), 3u) << p->title;
    EXPECT_EQ(p->bands[0].name, "drive stall (fault plan)");
    EXPECT_EQ(p->bands[0].x0, 0.2);
    EXPECT_EQ(p->bands[0].x1, 6.2);
    EXPECT_EQ(p->bands[1].name, "read error (drive retries)");
    EXPECT_EQ(p->bands[2].name, "contention (another client)");
    EXPECT_NE(p->bands[0].color, p->bands[1].color);
    EXPECT_NE(p->bands[1].color, p->bands[2].color);
  }
  EXPECT_TRUE(occupancyFigure("t", runs).panels[0].bands.empty());
}

TEST(ProfileFigures, StallCurveOneNestedLinePerKeyOnALog2Axis) {
  const std::vector<StallPoint> points{{"a, blend, pop", 8, 4.3},
                                       {"a, blend, late", 8, std::nullopt},  // fails without a stall
                                       {"a, blend, pop", 64, 12.0},
                                       {"a, blend, late", 64, 12.0}};
  const Figure f = stallFigure("t", points, {3.0, 12.0, -1});
  ASSERT_EQ(f.panels.size(), 1u);
  const Panel& p = f.panels[0];
  EXPECT_TRUE(p.xLog2);
  EXPECT_EQ(p.title, "Longest drive stall survived (stall at 3.0 s; pop threshold auto)");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].name, "a, blend, pop");  // first appearance
  EXPECT_EQ(p.series[0].x, (std::vector<double>{8, 64}));
  EXPECT_EQ(p.series[1].x, (std::vector<double>{64}));
  EXPECT_GT(p.series[0].thickness, p.series[1].thickness);  // drawn first, widest
  EXPECT_TRUE(p.series[0].markers);
  ASSERT_EQ(p.refLines.size(), 1u);
  EXPECT_EQ(p.refLines[0].name, "search limit 12 s");
  EXPECT_EQ(p.refLines[0].y, 12.0);
}

TEST(ProfileFigures, WritesEveryFigureAsPngAndSvg) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("vbim_profile_figures_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::vector<FaultInterval> stall{{"stall", 0.2, 0.6}};
  const std::vector<SweepTrace> sweep{{"day", "none", "blend-through", 4, 8, trace(4), stall},
                                      {"day", "none", "blend-through", 4, 64, trace(4), stall},
                                      {"day", "none", "hard-skip", 4, 8, trace(4), {}}};
  const std::vector<std::string> written =
      writeProfileFigures(sweep, {{"day, blend-through, pop", 8, 1.0}}, {3.0, 12.0, -1}, dir);
  const std::vector<std::string> expected{"plots/occupancy_day_none_blend-through.png",
                                          "plots/occupancy_day_none_blend-through.svg",
                                          "plots/lag_pop_day_none_blend-through.png",
                                          "plots/lag_pop_day_none_blend-through.svg",
                                          "plots/occupancy_day_none_hard-skip.png",
                                          "plots/occupancy_day_none_hard-skip.svg",
                                          "plots/lag_pop_day_none_hard-skip.png",
                                          "plots/lag_pop_day_none_hard-skip.svg",
                                          "plots/survivable_stall.png",
                                          "plots/survivable_stall.svg"};
  EXPECT_EQ(written, expected);
  for (const std::string& f : expected) EXPECT_GT(fs::file_size(dir / f), 1000u) << f;
  fs::remove_all(dir);
}

}  // namespace
