// The step shared by every hull scan: points of one line arrive from far to near (occluders come
// after the current point along the scan direction). The stack holds the upper convex hull of the
// points already seen; its top, after popping every point that lies on or below the line from the
// new point to the next one, is the new point's horizon point (docs/lighting.md#horizon-scan). Each
// point is pushed and popped at most once: O(n) per line. Slopes are compared by exact integer
// cross products, so the result is exactly the brute-force maximum.
#pragma once

#include <cstdint>

namespace vbim::lighting {

// Both fields are below 2^28 in magnitude (terrain.hpp bounds heights, callers bound positions), so
// the cross products below stay under 2^58.
struct HullPoint {
  std::int32_t x;  // position along the line, increasing in the scan direction
  std::int32_t h;  // height units
};

// The same with 64-bit fields, for sub-cell heights in fixed point (lighting/ray_sweep.hpp): callers
// keep |x| < 2^14 and |h| < 2^42, so the cross products stay under 2^57.
struct WideHullPoint {
  std::int64_t x;
  std::int64_t h;
};

// True when slope(p -> a) <= slope(p -> b), for a.x > p.x and b.x > p.x.
template <class Point>
inline bool slopeAtMost(const Point& p, const Point& a, const Point& b) {
  return (static_cast<std::int64_t>(a.h) - p.h) * (static_cast<std::int64_t>(b.x) - p.x) <=
         (static_cast<std::int64_t>(b.h) - p.h) * (static_cast<std::int64_t>(a.x) - p.x);
}

// Pushes p onto the hull stack [stack, stack + depth) and returns the horizon point of p (or nullptr
// when nothing lies ahead). `stride` separates consecutive stack levels (interleaved band stacks).
template <class Point>
inline const Point* hullPush(Point* stack, int& depth, int stride, const Point& p, Point& horizon) {
  while (depth >= 2 && slopeAtMost(p, stack[(depth - 1) * stride], stack[(depth - 2) * stride])) --depth;
  const Point* result = nullptr;
  if (depth >= 1) {
    horizon = stack[(depth - 1) * stride];
    result = &horizon;
  }
  stack[depth * stride] = p;
  ++depth;
  return result;
}

// The horizon point of a point p that is not pushed: the hull vertex of steepest slope from p, for p
// behind every point of the hull (p.x smaller). Seen from such a point the slopes along an upper hull
// rise, then fall (the hull is convex), so a binary search finds the peak in O(log depth).
template <class Point>
inline const Point* hullTangent(const Point* stack, int depth, const Point& p) {
  if (depth == 0) return nullptr;
  int lo = 0, hi = depth - 1;  // index 0 is the farthest point, depth - 1 the nearest
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (slopeAtMost(p, stack[mid - 1], stack[mid])) {
      lo = mid;  // the farther neighbour is no steeper: the peak is here or nearer
    } else {
      hi = mid - 1;
    }
  }
  return &stack[lo];
}

}  // namespace vbim::lighting
