#include "lighting/lightmap_inputs.hpp"

#include <utility>

#include "config/params_toml.hpp"
#include "lighting/image_files.hpp"
#include "runtime/param_table.hpp"

namespace vbim::lighting {

LightmapInputs lightmapInputs(TerrainSource source, const std::string& lightingConfig,
                              const std::function<void(DayCycleParams&)>& applyGiven) {
  LightmapInputs in;
  if (!lightingConfig.empty()) {
    ParamTable table;
    describeParams(table, in.params);
    config::applyTomlFile(table, lightingConfig);
  }
  if (applyGiven) applyGiven(in.params);
  validateParams(in.params);  // before any heavy work or output
  if (!source.cloudTexture.empty()) {
    in.cloudTexture = readDensityMap(source.cloudTexture);
    in.params.clouds.enabled = true;
  }
  source.procedural.cellSize = source.cellSize;
  in.terrain = loadTerrainAsIs(source);
  return in;
}

}  // namespace vbim::lighting
