// What `vbim lightmap` lights (lightmap_files.hpp writes the frames): the day from a lighting.* TOML
// file over the defaults and the command line's values over both, checked before any heavy work; the
// cloud texture; the terrain as it is (terrain_file.hpp).
#pragma once

#include <functional>
#include <string>

#include "lighting/day_cycle.hpp"
#include "lighting/float_image.hpp"
#include "lighting/terrain_file.hpp"

namespace vbim::lighting {

struct LightmapInputs {
  DayCycleParams params;
  FloatImage cloudTexture;  // empty without source.cloudTexture
  TerrainFile terrain;
};

// The keys of `lightingConfig` (if given) over the defaults, then `applyGiven` (the values given on
// the command line), validated; a cloud texture turns clouds on; the procedural terrain takes
// `source.cellSize` as its own. Throws LightingError or a config error naming the file.
LightmapInputs lightmapInputs(TerrainSource source, const std::string& lightingConfig,
                              const std::function<void(DayCycleParams&)>& applyGiven);

}  // namespace vbim::lighting
