#include "lighting/ray_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lighting/hull_scan.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr int kFracBits = 16;
constexpr std::int64_t kOne = std::int64_t{1} << kFracBits;
// Lines per cell across the azimuth: every texel's ray lies within 1 / (2 kLinesPerCell) cell of a
// line and is interpolated between the two lines beside it.
constexpr int kLineBits = 2;
constexpr int kSpacingBits = kFracBits - kLineBits;
constexpr std::int64_t kSpacing = std::int64_t{1} << kSpacingBits;
constexpr int kLinesPerItem = 32;
constexpr int kRowsPerItem = 64;

struct Geometry {
  bool majorIsCol;     // u = column when true, u = row otherwise
  bool forward;        // the azimuth points towards growing u: the far end is the last u
  int uSize, vSize;    // extents along the major and minor axes
  std::int64_t slope;  // minor / major component in 1/65536, |slope| <= 65536
  int jBegin, jEnd;    // lines (exclusive end) that can hold samples
  double tanScale;     // metres of rise per fixed-point height unit over metres of run per step

  std::size_t index(int u, int v, int width) const {
    return majorIsCol ? static_cast<std::size_t>(v) * width + u : static_cast<std::size_t>(u) * width + v;
  }
  std::int64_t position(int u) const { return forward ? u : -u; }
  // Texel (u, v)'s offset above line 0, in 1/65536 cell: v - u * tan.
  std::int64_t texelOffset(int u, int v) const { return v * kOne - u * slope; }
};

Geometry geometry(const Terrain& t, double azimuth) {
  const double cx = std::cos(azimuth), cy = std::sin(azimuth);
  Geometry g{};
  g.majorIsCol = std::fabs(cx) >= std::fabs(cy);
  const double major = g.majorIsCol ? cx : cy, minor = g.majorIsCol ? cy : cx;
  g.forward = major > 0;
  g.uSize = g.majorIsCol ? t.width : t.height;
  g.vSize = g.majorIsCol ? t.height : t.width;
  g.slope = std::clamp<std::int64_t>(std::llround(minor / major * kOne), -kOne, kOne);
  const std::int64_t shiftFar = (g.uSize - 1) * g.slope;  // u * slope at the last u
  const std::int64_t lo = std::min<std::int64_t>(0, -shiftFar), hi = std::max<std::int64_t>(0, -shiftFar);
  g.jBegin = static_cast<int>(lo >> kSpacingBits);  // floor
  g.jEnd = (g.vSize << kLineBits) + static_cast<int>((hi + kSpacing - 1) >> kSpacingBits) + 1;
  const double q = static_cast<double>(g.slope) / kOne;
  g.tanScale = t.heightStep / kOne / (t.cellSize * std::sqrt(1 + q * q));
  return g;
}

float horizonTan(const WideHullPoint* top, const WideHullPoint& p, double scale) {
  if (top == nullptr || top->h <= p.h) return 0.0f;
  return static_cast<float>(static_cast<double>(top->h - p.h) / static_cast<double>(top->x - p.x) * scale);
}

// Line j's sample at step u (false when the line is outside the grid there).
bool lineSample(const Terrain& t, const Geometry& g, int j, int u, WideHullPoint& out) {
  const std::int64_t c = j * kSpacing + u * g.slope;
  const std::int64_t v0 = c >> kFracBits, frac = c & (kOne - 1);
  if (v0 < 0 || v0 >= g.vSize || (frac != 0 && v0 + 1 >= g.vSize)) return false;
  const std::int64_t h0 = t.heights[g.index(u, static_cast<int>(v0), t.width)];
  const std::int64_t h1 = frac != 0 ? t.heights[g.index(u, static_cast<int>(v0) + 1, t.width)] : h0;
  out = {g.position(u), h0 * kOne + frac * (h1 - h0)};
  return true;
}

// One line, far end first: before its own sample at u is pushed, the hull holds every sample ahead;
// the two texels between this line and its neighbours at u ask it for their horizon. `lower[i]`
// receives texel i's answer from the line below it (at or under its offset), `upper[i]` from the line
// above. Every texel has exactly one of each, so bands of lines can run in parallel.
void sweepLine(const Terrain& t, const Geometry& g, int j, std::vector<WideHullPoint>& stack, float* lower,
               float* upper) {
  stack.resize(static_cast<std::size_t>(g.uSize) + 1);
  int depth = 0;
  for (int k = 0; k < g.uSize; ++k) {
    const int u = g.forward ? g.uSize - 1 - k : k;
    const std::int64_t c = j * kSpacing + u * g.slope;
    const std::int64_t above = (c + kOne - 1) >> kFracBits;  // the texel at or just above the line
    const std::int64_t frac = above * kOne - c;              // its offset above the line, [0, 1) cell
    const std::int64_t x = g.position(u);
    if (frac < kSpacing && above >= 0 && above < g.vSize) {
      const std::size_t i = g.index(u, static_cast<int>(above), t.width);
      const WideHullPoint p{x, std::int64_t{t.heights[i]} * kOne};
      lower[i] = horizonTan(hullTangent(stack.data(), depth, p), p, g.tanScale);
    }
    if (kOne - frac < kSpacing && above - 1 >= 0 && above - 1 < g.vSize) {
      const std::size_t i = g.index(u, static_cast<int>(above - 1), t.width);
      const WideHullPoint p{x, std::int64_t{t.heights[i]} * kOne};
      upper[i] = horizonTan(hullTangent(stack.data(), depth, p), p, g.tanScale);
    }
    WideHullPoint s;
    if (lineSample(t, g, j, u, s)) {
      WideHullPoint unused;
      hullPush(stack.data(), depth, 1, s, unused);
    }
  }
}

// out = (1 - f) lower + f upper, f = the texel's offset above its lower line.
void blendRows(const Terrain& t, const Geometry& g, int r0, int r1, float* out, const float* upper) {
  for (int r = r0; r < r1; ++r) {
    for (int c = 0; c < t.width; ++c) {
      const int u = g.majorIsCol ? c : r, v = g.majorIsCol ? r : c;
      const std::int64_t frac = g.texelOffset(u, v) & (kSpacing - 1);
      const std::size_t i = static_cast<std::size_t>(r) * t.width + c;
      if (frac != 0) {
        const float f = static_cast<float>(frac) / static_cast<float>(kSpacing);
        out[i] = out[i] + f * (upper[i] - out[i]);
      }
    }
  }
}

template <class Fn>
void forEach(std::size_t n, WorkerPool* pool, const Fn& fn) {
  if (pool != nullptr) {
    pool->parallelFor(n, fn);
  } else {
    for (std::size_t i = 0; i < n; ++i) fn(i);
  }
}

}  // namespace

void sweepRays(const Terrain& t, double azimuth, float* out, WorkerPool* pool) {
  const Geometry g = geometry(t, azimuth);
  std::vector<float> upper(t.texels(), 0.0f);
  const int lines = g.jEnd - g.jBegin;
  forEach(static_cast<std::size_t>((lines + kLinesPerItem - 1) / kLinesPerItem), pool, [&](std::size_t item) {
    thread_local std::vector<WideHullPoint> stack;
    const int j0 = g.jBegin + static_cast<int>(item) * kLinesPerItem;
    for (int j = j0; j < std::min(g.jEnd, j0 + kLinesPerItem); ++j) sweepLine(t, g, j, stack, out, upper.data());
  });
  forEach(static_cast<std::size_t>((t.height + kRowsPerItem - 1) / kRowsPerItem), pool, [&](std::size_t item) {
    const int r0 = static_cast<int>(item) * kRowsPerItem;
    blendRows(t, g, r0, std::min(t.height, r0 + kRowsPerItem), out, upper.data());
  });
}

void sweepRaysBruteForce(const Terrain& t, double azimuth, float* out) {
  const Geometry g = geometry(t, azimuth);
  std::vector<float> upper(t.texels(), 0.0f);
  for (int u = 0; u < g.uSize; ++u) {
    for (int v = 0; v < g.vSize; ++v) {
      const std::size_t i = g.index(u, v, t.width);
      const std::int64_t offset = g.texelOffset(u, v);
      const int below = static_cast<int>(offset >> kSpacingBits);
      const WideHullPoint p{g.position(u), std::int64_t{t.heights[i]} * kOne};
      for (int side = 0; side < 2; ++side) {
        if (side == 1 && (offset & (kSpacing - 1)) == 0) break;
        const int j = below + side;
        const WideHullPoint* best = nullptr;
        WideHullPoint bestPoint{}, s{};
        for (int uu = 0; uu < g.uSize; ++uu) {
          if (!lineSample(t, g, j, uu, s) || s.x <= p.x) continue;
          if (best == nullptr || !slopeAtMost(p, s, bestPoint)) {
            bestPoint = s;
            best = &bestPoint;
          }
        }
        (side == 0 ? out : upper.data())[i] = horizonTan(best, p, g.tanScale);
      }
    }
  }
  blendRows(t, g, 0, t.height, out, upper.data());
}

}  // namespace vbim::lighting
