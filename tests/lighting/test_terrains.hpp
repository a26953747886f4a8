// Small terrains shared by the lighting tests.
#pragma once

#include <cstdint>
#include <vector>

#include "lighting/terrain.hpp"
#include "runtime/rng.hpp"

namespace vbim::lighting::testing {

// Random integer heights in [0, range): small ranges give many ties and plateaus.
inline Terrain randomTerrain(int w, int h, std::uint64_t seed, std::uint32_t range, double cell = 10.0) {
  Rng rng(seed);
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(w) * h);
  for (auto& c : counts) c = static_cast<std::uint32_t>(rng.below(range));
  return terrainFromCounts(w, h, counts, cell, 0.25, "random");
}

inline Terrain flatTerrain(int w, int h, double cell = 10.0) {
  return terrainFromCounts(w, h, std::vector<std::uint32_t>(static_cast<std::size_t>(w) * h, 100), cell, 1.0, "flat");
}

// A plane rising towards +row (south) at `slope` = rise / run.
inline Terrain slopeTerrain(int w, int h, double slope, double cell = 10.0) {
  std::vector<float> m(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m[static_cast<std::size_t>(y) * w + x] = static_cast<float>(y * cell * slope);
  return terrainFromMetres(w, h, m, cell, "slope");
}

}  // namespace vbim::lighting::testing
