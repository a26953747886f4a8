// vbim lightmap: Technique A frames (lightmaps + sky domes) from a heightfield, as image files
// (runs::lightmapRun, runs/lightmap_run.hpp).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/host_threads.hpp"
#include "cli/lighting_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "runs/lightmap_run.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::lighting;

struct LightmapOptions {
  runs::LightmapRequest request;  // the terrain's *Given flags and the overrides set after parsing
  bool noMoon = false;
  DayCycleParams params;  // values given on the command line
};

void run(const runs::LightmapRequest& r) {
  std::optional<Progress> progress;  // from the first frame's call: the rate counts the frames only
  runs::LightmapObserver observer;
  observer.onTerrainNote = [](const std::string& note) { std::printf("vbim lightmap: %s\n", note.c_str()); };
  observer.onProgress = [&progress](int done, int total) {
    if (!progress) progress.emplace("vbim lightmap", "frames");
    progress->show(done, total);
  };
  const std::string summary = runs::lightmapRun(r, observer);
  if (progress) progress->finish();
  std::printf("vbim lightmap: %s\n", summary.c_str());
}

}  // namespace

void addLightmap(CLI::App& app) {
  auto* cmd = app.add_subcommand(kLightmapCommand.name, kLightmapCommand.summary);
  auto o = std::make_shared<LightmapOptions>();
  auto given = std::make_shared<LightingOverrides>();
  cmd->add_option("--terrain", o->request.terrain.heightfield,
                  "Heightfield (single-channel; 16-bit PNG, TIFF, EXR...). Default: built-in procedural terrain");
  cmd->add_option("--bounce-albedo", o->request.terrain.bounceAlbedo,
                  "Colour (albedo) of the surrounding terrain for the coloured bounce light only, same size "
                  "(default: the texel's own albedo)");
  cmd->add_option("--albedo", o->request.terrain.albedo,
                  "Diffuse colour map, same size as the heightfield (8/16-bit = sRGB, float = linear)");
  CLI::Option* cellSize = cmd->add_option("--cell-size", o->request.terrain.cellSize,
                                          "Metres between heightfield samples (a DEM's own unless given)")
                              ->default_val(10.0);
  CLI::Option* verticalScale =
      cmd->add_option("--vertical-scale", o->request.terrain.verticalScale,
                      "Metres at full scale for integer heightfields; a multiplier for float ones and DEMs (heights "
                      "in metres are used as they are unless given)")
          ->default_val(1000.0);
  cmd->add_option("--size", o->request.terrain.procedural.size, "Procedural terrain size in texels")->default_val(512);
  cmd->add_option("--seed", o->request.terrain.procedural.seed, "Procedural terrain seed")->default_val(1);
  cmd->add_option("--relief", o->request.terrain.procedural.reliefMetres, "Procedural terrain relief in metres")
      ->default_val(900.0);
  cmd->add_option("--cloud-texture", o->request.terrain.cloudTexture,
                  "Single-channel cloud density texture (implies --clouds)");
  addLightingOptions(cmd, o->params, o->noMoon, *given, LightingOptionNames{}, [](CLI::Option*) {});
  cmd->add_option("--config", o->request.config, "TOML file of lighting.* parameters (command-line values win)")
      ->check(inputFile());
  cmd->add_option("--format", o->request.files.format,
                  "png, exr, both (png and exr), or tif (lightmaps as GeoTIFF with the DEM's georeferencing, sky "
                  "domes as exr)")
      ->default_val("png")
      ->check(oneOf("--format", {"png", "exr", "both", "tif"}));
  cmd->add_option("--debug", o->request.files.debug,
                  "Extra layers: horizons, sky (factor K), shadow (sun mask), nl (N.L of the key light), or all");
  cmd->add_option("--layers-format", o->request.files.layersFormat,
                  "Float debug layers as exr, or tif (GeoTIFF with the DEM's georeferencing)")
      ->default_val("exr")
      ->check(oneOf("--layers-format", {"exr", "tif"}));
  addThreadsOption(*cmd, o->request.files.threads, "Host threads that compute the lighting");
  cmd->add_option("-o,--out", o->request.out, "Output directory (complete or absent)")->required();
  cmd->add_flag("--force", o->request.force, "Replace an existing non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim lightmap --out lm/\n"
      "  vbim lightmap --size 256 --frames 24 --debug all --format both --out lm/\n");
  cmd->callback([o, given, cellSize, verticalScale] {
    o->request.terrain.cellSizeGiven = cellSize->count() > 0;
    o->request.terrain.verticalScaleGiven = verticalScale->count() > 0;
    o->request.applyGiven = [given](DayCycleParams& params) { applyGivenLightingOptions(*given, params); };
    run(o->request);
  });
}

}  // namespace vbim::cli
