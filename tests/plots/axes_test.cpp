// Axis ranges and tick labels of a chart: round steps, headroom, log2 axes.
#include <gtest/gtest.h>

#include <cmath>

#include "plots/axes.hpp"

namespace {

using namespace vbim::plots;

TEST(PlotAxes, NiceTicksAreRoundAndCoverTheRange) {
  EXPECT_EQ(niceTicks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(niceTicks(0, 105, 6), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  EXPECT_TRUE(niceTicks(1, 1, 5).empty());
  const std::vector<double> t = niceTicks(0, 0.25, 6);
  ASSERT_GE(t.size(), 2u);
  EXPECT_NEAR(t[1] - t[0], 0.05, 1e-12);
}

TEST(PlotAxes, YAxisStartsAtZeroForPositiveDataWithHeadroom) {
  Panel p;
  p.series.push_back(Series{"a", {}, {0, 1, 2}, {3, 50, 67}});
  const Axis y = yAxis(p);
  EXPECT_EQ(y.lo, 0);
  EXPECT_DOUBLE_EQ(y.hi, 67 * 1.08);
  EXPECT_EQ(y.step, 20);
  p.yMin = 0;
  p.yMax = 105;
  EXPECT_EQ(yAxis(p).hi, 105);
}

TEST(PlotAxes, ReferenceLinesAreInTheYRange) {
  Panel p;
  p.series.push_back(Series{"a", {}, {0, 1}, {1, 2}});
  p.refLines.push_back(RefLine{"limit", 12});
  EXPECT_GE(yAxis(p).hi, 12);
}

TEST(PlotAxes, Log2AxisHasRoomAndPowerOfTwoLabels) {
  Figure f;
  Panel p;
  p.xLog2 = true;
  p.series.push_back(Series{"a", {}, {8, 64}, {1, 2}});
  f.panels.push_back(p);
  const Axis x = xAxis(f);
  EXPECT_TRUE(x.log2);
  EXPECT_NEAR(x.lo, std::log2(8 / 1.25), 1e-12);
  EXPECT_NEAR(x.hi, std::log2(64 * 1.25), 1e-12);
  EXPECT_EQ(x.step, 1);
  EXPECT_EQ(tickLabel(x, 4), "16");
  EXPECT_EQ(x.toDrawing(32), 5);
}

TEST(PlotAxes, TickLabelsHaveTheDecimalsTheStepNeeds) {
  Axis a;
  a.step = 0.2;
  EXPECT_EQ(tickLabel(a, 0.4), "0.4");
  EXPECT_EQ(tickLabel(a, 1e-17), "0.0");
  a.step = 5;
  EXPECT_EQ(tickLabel(a, 10), "10");
}

}  // namespace
