// The built-in terrain, so nothing is needed to start: ridged mountains over rolling hills with a
// flat valley floor, from integer-hashed value noise (the same seed gives the same heights on every
// machine: only +, *, / and comparisons on doubles), and a matching albedo (grass, rock, snow).
#pragma once

#include <cstdint>

#include "lighting/terrain.hpp"

namespace vbim::lighting {

struct ProceduralTerrainParams {
  std::int64_t size = 512;      // texels per side
  double cellSize = 10.0;       // metres
  double reliefMetres = 900.0;  // highest peak above the valley floor
  std::int64_t seed = 1;
};

Terrain proceduralTerrain(const ProceduralTerrainParams& p);

// Grass on gentle low slopes, rock on steep ones, snow high up: linear RGB in [0, 1].
FloatImage proceduralAlbedo(const Terrain& terrain);

}  // namespace vbim::lighting
