#include "runs/lightmap_run.hpp"

#include <utility>

#include "lighting/lightmap_inputs.hpp"
#include "runs/output_dir.hpp"

namespace vbim::runs {

std::string lightmapRun(const LightmapRequest& r, const LightmapObserver& observer) {
  lighting::checkLightmapRequest(r.files);
  lighting::LightmapInputs in = lighting::lightmapInputs(r.terrain, r.config, r.applyGiven);
  if (observer.onTerrainNote) {
    for (const std::string& note : in.terrain.notes) observer.onTerrainNote(r.terrain.heightfield + ": " + note);
  }
  OutputDir dir(r.out, r.force);
  const lighting::LightmapFiles written =
      lighting::writeLightmapFiles(r.files, std::move(in.terrain), in.params, std::move(in.cloudTexture),
                                   dir.directory(), [&observer](int done, int total) {
                                     if (observer.onProgress) observer.onProgress(done, total);
                                   });
  dir.commit();
  return std::to_string(written.frames) + " frames (" + std::to_string(written.width) + "x" +
         std::to_string(written.height) + " lightmaps, " + std::to_string(in.params.skyWidth) + "x" +
         std::to_string(in.params.skyWidth / 2) + " sky domes) in " + r.out;
}

}  // namespace vbim::runs
