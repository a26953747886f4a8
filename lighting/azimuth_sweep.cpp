#include "lighting/azimuth_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lighting/hull_scan.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr double kPosOne = 4096.0;  // fixed-point units per cell along the projection
constexpr int kLinesPerItem = 32;

struct Geometry {
  bool majorIsCol;      // u = column when true, u = row otherwise
  int uSize, vSize;     // extents along the major and minor axes
  double slope;         // minor / major component, |slope| <= 1
  std::int32_t du, dv;  // fixed-point projection of one step along u and v onto the azimuth
  int offMin, offMax;   // range of round(u * slope)
  double tanScale;      // metres of rise per height unit over metres of run per position unit

  int offset(int u) const { return static_cast<int>(std::floor(u * slope + 0.5)); }
  int lineBegin() const { return -offMax; }
  int lineEnd() const { return vSize - offMin; }  // exclusive
  std::size_t index(int u, int v, int width) const {
    return majorIsCol ? static_cast<std::size_t>(v) * width + u : static_cast<std::size_t>(u) * width + v;
  }
};

Geometry geometry(const Terrain& t, double azimuth) {
  const double cx = std::cos(azimuth), cy = std::sin(azimuth);
  Geometry g{};
  g.majorIsCol = std::fabs(cx) >= std::fabs(cy);
  const double major = g.majorIsCol ? cx : cy, minor = g.majorIsCol ? cy : cx;
  g.uSize = g.majorIsCol ? t.width : t.height;
  g.vSize = g.majorIsCol ? t.height : t.width;
  g.slope = minor / major;
  g.du = static_cast<std::int32_t>(std::lround(major * kPosOne));
  g.dv = static_cast<std::int32_t>(std::lround(minor * kPosOne));
  const int a = g.offset(0), b = g.offset(g.uSize - 1);
  g.offMin = std::min(a, b);
  g.offMax = std::max(a, b);
  g.tanScale = t.heightStep / (t.cellSize / kPosOne);
  return g;
}

float horizonTan(const HullPoint* top, const HullPoint& p, double scale) {
  if (top == nullptr || top->h <= p.h) return 0.0f;
  return static_cast<float>(static_cast<double>(top->h - p.h) / static_cast<double>(top->x - p.x) * scale);
}

void sweepLines(const Terrain& t, const Geometry& g, const std::vector<int>& offsets, int j0, int j1, float* out) {
  thread_local std::vector<HullPoint> stack;
  stack.resize(static_cast<std::size_t>(g.uSize));
  const bool forward = g.du > 0;  // positions grow with u: the far end is the last u
  const std::ptrdiff_t su = g.majorIsCol ? 1 : t.width, sv = g.majorIsCol ? t.width : 1;
  const std::int32_t* heights = t.heights.data();
  for (int j = j0; j < j1; ++j) {
    int depth = 0;
    for (int k = 0; k < g.uSize; ++k) {
      const int u = forward ? g.uSize - 1 - k : k;
      const int v = j + offsets[static_cast<std::size_t>(u)];
      if (v < 0 || v >= g.vSize) continue;
      const std::ptrdiff_t i = u * su + v * sv;
      const HullPoint p{u * g.du + v * g.dv, heights[i]};
      HullPoint hp;
      out[i] = horizonTan(hullPush(stack.data(), depth, 1, p, hp), p, g.tanScale);
    }
  }
}

}  // namespace

void sweepAzimuth(const Terrain& t, double azimuth, float* out, WorkerPool* pool) {
  const Geometry g = geometry(t, azimuth);
  std::vector<int> offsets(static_cast<std::size_t>(g.uSize));
  for (int u = 0; u < g.uSize; ++u) offsets[static_cast<std::size_t>(u)] = g.offset(u);
  const int lines = g.lineEnd() - g.lineBegin();
  const int items = (lines + kLinesPerItem - 1) / kLinesPerItem;
  auto run = [&](std::size_t item) {
    const int j0 = g.lineBegin() + static_cast<int>(item) * kLinesPerItem;
    sweepLines(t, g, offsets, j0, std::min(g.lineEnd(), j0 + kLinesPerItem), out);
  };
  if (pool != nullptr) {
    pool->parallelFor(static_cast<std::size_t>(items), run);
  } else {
    for (int i = 0; i < items; ++i) run(static_cast<std::size_t>(i));
  }
}

void sweepAzimuthBruteForce(const Terrain& t, double azimuth, float* out) {
  const Geometry g = geometry(t, azimuth);
  for (int j = g.lineBegin(); j < g.lineEnd(); ++j) {
    std::vector<HullPoint> line;  // in order of u
    std::vector<std::size_t> where;
    for (int u = 0; u < g.uSize; ++u) {
      const int v = j + g.offset(u);
      if (v < 0 || v >= g.vSize) continue;
      where.push_back(g.index(u, v, t.width));
      line.push_back({u * g.du + v * g.dv, t.heights[where.back()]});
    }
    for (std::size_t a = 0; a < line.size(); ++a) {
      const HullPoint* best = nullptr;
      for (std::size_t b = 0; b < line.size(); ++b) {
        if (line[b].x <= line[a].x) continue;
        if (best == nullptr || !slopeAtMost(line[a], line[b], *best)) best = &line[b];
      }
      out[where[a]] = horizonTan(best, line[a], g.tanScale);
    }
  }
}

}  // namespace vbim::lighting
