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

// True when slope(p -> a) <= slope(p -> b), for a.x > p.x and b.x > p.x.
inline bool slopeAtMost(const HullPoint& p, const HullPoint& a, const HullPoint& b) {
  return std::int64_t{a.h - p.h} * (b.x - p.x) <= std::int64_t{b.h - p.h} * (a.x - p.x);
}

// Pushes p onto the hull stack [stack, stack + depth) and returns the horizon point of p (or nullptr
// when nothing lies ahead). `stride` separates consecutive stack levels (interleaved band stacks).
inline const HullPoint* hullPush(HullPoint* stack, int& depth, int stride, const HullPoint& p, HullPoint& horizon) {
  while (depth >= 2 && slopeAtMost(p, stack[(depth - 1) * stride], stack[(depth - 2) * stride])) --depth;
  const HullPoint* result = nullptr;
  if (depth >= 1) {
    horizon = stack[(depth - 1) * stride];
    result = &horizon;
  }
  stack[depth * stride] = p;
  ++depth;
  return result;
}

}  // namespace vbim::lighting
