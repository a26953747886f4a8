// The 256-entry normal palette (Hoffman & Mitchell: "we quantize all the terrain normals into a
// table of 256 normals and store a table index for each terrain point"). Per frame only the 256
// palette normals are lit (N . L); each texel looks its value up by index.
//
// The palette is fitted to the terrain (docs/lighting.md#normal-palette: a uniform hemisphere palette
// errs by up to 8.7 deg, enough to band at grazing sun): Fibonacci points on the cap that holds the
// terrain's normals, then k-means (Lloyd) iterations on a deterministic subsample. Each texel gets
// its exact nearest entry (ties to the lower index) through a bucket search over (n_x, n_y).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lighting/terrain.hpp"

namespace vbim::lighting {

inline constexpr int kPaletteSize = 256;

struct NormalPalette {
  std::array<Vec3, kPaletteSize> normals{};
  std::vector<std::uint8_t> index;  // per texel
};

NormalPalette buildNormalPalette(const std::vector<Vec3>& normals, int kmeansIterations = 8);

// Largest angle (radians) between a texel's normal and its palette normal: for reports and tests.
double maxPaletteError(const NormalPalette& palette, const std::vector<Vec3>& normals);

}  // namespace vbim::lighting
