#include "plots/axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vbim::plots {

namespace {

struct Extent {
  double lo = 0, hi = 0;
  bool any = false;
  void add(double v) {
    lo = any ? std::min(lo, v) : v;
    hi = any ? std::max(hi, v) : v;
    any = true;
  }
};

double stepOf(const std::vector<double>& ticks) {
  return ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
}

}  // namespace

double Axis::toDrawing(double v) const {
  return log2 ? std::log2(v) : v;
}

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> t;
  if (!(hi > lo) || target < 1) return t;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double v = first; v <= hi + step * 1e-9 && t.size() < 100; v += step) t.push_back(v);
  return t;
}

Axis xAxis(const Figure& fig) {
  Extent e;
  bool log2 = false;
  for (const Panel& p : fig.panels) {
    log2 = log2 || p.xLog2;
    for (const Series& s : p.series)
      for (double v : s.x) e.add(v);
  }
  Axis a;
  a.log2 = log2;
  if (log2) {
    const double lo = std::max(e.any ? e.lo : 1.0, 1e-9) / 1.25;
    const double hi = std::max(e.any ? e.hi : 1.0, lo * 2) * 1.25;
    a.lo = std::log2(lo);
    a.hi = std::log2(hi);
    a.step = 1;  // one tick per power of two
    return a;
  }
  a.lo = e.lo;
  a.hi = e.hi > e.lo ? e.hi : e.lo + 1;
  a.step = stepOf(niceTicks(a.lo, a.hi, 10));
  return a;
}

Axis yAxis(const Panel& panel) {
  Extent e;
  for (const Series& s : panel.series)
    for (double v : s.y) e.add(v);
  for (const RefLine& r : panel.refLines) e.add(r.y);
  double lo = std::min(e.lo, 0.0);
  double hi = e.hi;
  if (hi <= lo) hi = lo + 1;
  hi += (hi - lo) * 0.08;
  if (panel.yMin) lo = *panel.yMin;
  if (panel.yMax) hi = *panel.yMax;
  Axis a;
  a.lo = lo;
  a.hi = hi;
  a.step = stepOf(niceTicks(lo, hi, 6));
  return a;
}

std::string tickLabel(const Axis& axis, double v) {
  char b[32];
  if (axis.log2) {
    std::snprintf(b, sizeof b, "%.0f", std::exp2(v));
    return b;
  }
  const double step = axis.step;
  if (std::abs(v) < step * 1e-6) v = 0;
  if (step >= 1 || std::abs(step - std::round(step)) < 1e-9) {
    std::snprintf(b, sizeof b, "%.0f", v);
  } else {
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 1, 4);
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
  }
  return b;
}

}  // namespace vbim::plots
