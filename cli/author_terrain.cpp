#include "cli/author_terrain.hpp"

#include <map>

#include "cli/host_threads.hpp"
#include "cli/lighting_options.hpp"
#include "cli/option_checks.hpp"

namespace vbim::cli {

void addTerrainOptions(CLI::App* cmd, const std::shared_ptr<TerrainAuthorOptions>& o) {
  const std::string group = "Technique A (--terrain FILE or --procedural)";
  auto track = [&](CLI::Option* opt) {
    opt->group(group);
    o->options.push_back(opt);
    return opt;
  };
  track(cmd->add_option("--terrain", o->request.terrain.heightfield,
                        "Heightfield: a DEM GDAL reads (GeoTIFF, ASCII grid, .hgt...) or a single-channel picture "
                        "(16-bit PNG, TIFF, EXR...)"));
  track(cmd->add_flag("--procedural", o->request.procedural,
                      "Use the built-in procedural terrain (also what any Technique A option without --terrain gets)"));
  const std::map<std::string, lighting::TerrainFit> fits{
      {"crop", lighting::TerrainFit::Crop}, {"pad", lighting::TerrainFit::Pad}, {"none", lighting::TerrainFit::None}};
  track(cmd->add_option("--terrain-fit", o->request.terrain.fit,
                        "Sides not multiples of 16: crop (centred), pad (edges repeated) or none (refused)")
            ->transform(CLI::CheckedTransformer(fits))
            ->default_str("crop"));
  track(cmd->add_option(
      "--albedo", o->request.terrain.albedo,
      "Diffuse colour map of the terrain's size or of the heightfield file's (then resampled with it)"));
  track(cmd->add_option("--bounce-albedo", o->request.terrain.bounceAlbedo,
                        "Colour of the surrounding terrain for the coloured bounce light only (same size)"));
  track(cmd->add_option("--cloud-texture", o->request.terrain.cloudTexture,
                        "Single-channel cloud density texture (implies --clouds)"));
  o->cellSizeOption = track(cmd->add_option("--cell-size", o->request.terrain.cellSize,
                                            "Metres between heightfield samples (a DEM's own unless given)")
                                ->default_val(10.0));
  o->verticalScaleOption =
      track(cmd->add_option("--vertical-scale", o->request.terrain.verticalScale,
                            "Metres at full scale for integer heightfields; a multiplier for float ones and DEMs "
                            "(heights in metres are used as they are unless given)")
                ->default_val(1000.0));
  track(cmd->add_option("--size", o->request.terrain.procedural.size,
                        "Procedural terrain size in texels (multiple of 16); the default "
                        "fits the default platform config's VRAM next to the sky")
            ->default_val(256));
  track(cmd->add_option("--seed", o->request.terrain.procedural.seed, "Procedural terrain seed")->default_val(1));
  track(cmd->add_option("--relief", o->request.terrain.procedural.reliefMetres, "Procedural terrain relief in metres")
            ->default_val(900.0));
  // The plain pointer inside the stored functions (not the shared_ptr) keeps `o` from owning
  // itself, which LeakSanitizer would report.
  addLightingOptions(cmd, o->params, o->noMoon, o->given, LightingOptionNames{"--frame-count", "--exposure-klux"},
                     [&](CLI::Option* opt) { track(opt); });
  track(cmd->add_option("--lighting-config", o->request.lightingConfig,
                        "TOML file of lighting.* keys (command-line options win)")
            ->check(inputFile()));
  track(cmd->add_option("--weather", o->request.weather,
                        "Variants: presets clear, overcast, or NAME=FILE.toml (lighting.* over the base), "
                        "comma-separated")
            ->capture_default_str());
  track(cmd->add_option("--threads", o->request.threads, "Host threads (the output does not depend on it)")
            ->default_val(2)
            ->check(hostThreads()));
}

std::string firstTerrainOptionGiven(const TerrainAuthorOptions& o) {
  for (const CLI::Option* opt : o.options)
    if (opt->count() > 0) return opt->get_name();
  return "";
}

lighting::TerrainAuthorRequest terrainRequest(const TerrainAuthorOptions& o) {
  lighting::TerrainAuthorRequest request = o.request;
  request.terrain.cellSizeGiven = o.cellSizeOption != nullptr && o.cellSizeOption->count() > 0;
  request.terrain.verticalScaleGiven = o.verticalScaleOption != nullptr && o.verticalScaleOption->count() > 0;
  // `o` outlives the run (the app's callback holds it).
  request.applyGiven = [&o](lighting::DayCycleParams& params) { applyGivenLightingOptions(o.given, params); };
  return request;
}

}  // namespace vbim::cli
