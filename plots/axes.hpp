// The axes of a chart: ranges and tick spacing chosen from the data (round steps of 1, 2 or 5 x 10^k;
// powers of two on a log2 axis) and the tick labels. Pure arithmetic, no drawing.
#pragma once

#include <string>
#include <vector>

#include "plots/chart.hpp"

namespace vbim::plots {

struct Axis {
  double lo = 0, hi = 1;  // in drawing coordinates: log2 of the data on a log2 axis
  double step = 1;        // between major ticks, in drawing coordinates
  bool log2 = false;

  double toDrawing(double v) const;  // data value -> drawing coordinate
};

// The x axis all panels share: the range of every series' x (a log2 axis gets a quarter of a
// doubling of room on both sides), about ten ticks.
Axis xAxis(const Figure& fig);

// A panel's y axis: the data and reference lines, 0 included when all are >= 0, 8 % headroom (or
// the panel's yMin / yMax); about six ticks.
Axis yAxis(const Panel& panel);

// Ticks between lo and hi: about `target` round values (1, 2, 5 x 10^k), inclusive of the range.
std::vector<double> niceTicks(double lo, double hi, int target);

// The label of the tick at drawing coordinate `v`: integers when the step is whole, otherwise as
// many decimals as the step needs (at most 4); 2^v on a log2 axis.
std::string tickLabel(const Axis& axis, double v);

}  // namespace vbim::plots
