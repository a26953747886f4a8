// Horizon maps in the 8 grid directions (rows, columns, diagonals), one exact O(n) convex-hull scan
// per grid line (Dozier, Bruno & Downey 1981; Barrett 2011; docs/lighting.md#horizon-scan).
//
// Direction d points at azimuth d * pi/4 in the (col, row, up) basis: 0 = E (+col), 1 = SE,
// 2 = S (+row), 3 = SW, 4 = W, 5 = NW, 6 = N, 7 = NE. The horizon of texel p in direction d is the
// largest elevation angle from p to any texel p + k*d, k >= 1, clamped at 0 (the sky is only above
// the horizontal: docs/lighting.md#sector-centring-and-clamps), stored as a 16-bit fixed-point code
// (lighting/fixed_angle.hpp).
//
// Every direction scans the whole map: with a linear-time scan the full range costs less than the
// article's short brute-force scans did, so nothing is gained by cutting the range short.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lighting/terrain.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::lighting {

inline constexpr int kDirections = 8;
struct GridStep {
  int dc, dr;
};
inline constexpr std::array<GridStep, kDirections> kGridSteps{
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
inline constexpr std::array<const char*, kDirections> kDirectionNames{"E", "SE", "S", "SW", "W", "NW", "N", "NE"};

struct HorizonMaps {
  int width = 0;
  int height = 0;
  std::array<std::vector<std::uint16_t>, kDirections> code;  // per direction, width * height
};

// All 8 directions. With a pool, directions and bands of lines run in parallel; the result does not
// depend on the number of threads.
HorizonMaps computeHorizons(const Terrain& terrain, WorkerPool* pool = nullptr);

// One direction with the O(n) hull scan; `out` has width * height entries.
void scanHorizon(const Terrain& terrain, int direction, std::uint16_t* out);

// The O(n^2) reference: every texel tests every texel ahead of it. Tests only.
void scanHorizonBruteForce(const Terrain& terrain, int direction, std::uint16_t* out);

}  // namespace vbim::lighting
