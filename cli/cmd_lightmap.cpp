// vbim lightmap: Technique A frames (lightmaps + sky domes) from a heightfield, as image files
// (lighting/lightmap_inputs.hpp, lighting/lightmap_files.hpp).
#include <cstdio>
#include <memory>
#include <utility>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/host_threads.hpp"
#include "cli/lighting_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "lighting/lightmap_files.hpp"
#include "lighting/lightmap_inputs.hpp"
#include "runs/output_dir.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::lighting;

struct LightmapOptions {
  TerrainSource terrain;  // its *Given flags set after parsing: overrides for a DEM
  std::string config, out;
  LightmapFilesRequest files;  // --format, --debug, --layers-format, --threads
  bool force = false, noMoon = false;
  DayCycleParams params;  // values given on the command line
};

void run(LightmapOptions& o, const LightingOverrides& given) {
  checkLightmapRequest(o.files);
  LightmapInputs in = lightmapInputs(o.terrain, o.config,
                                     [&given](DayCycleParams& params) { applyGivenLightingOptions(given, params); });
  for (const std::string& note : in.terrain.notes)
    std::printf("vbim lightmap: %s: %s\n", o.terrain.heightfield.c_str(), note.c_str());

  runs::OutputDir dir(o.out, o.force);
  Progress progress("vbim lightmap", "frames");
  const LightmapFiles written =
      writeLightmapFiles(o.files, std::move(in.terrain), in.params, std::move(in.cloudTexture), dir.directory(),
                         [&](int done, int total) { progress.show(done, total); });
  progress.finish();
  dir.commit();
  std::printf("vbim lightmap: %d frames (%dx%d lightmaps, %lldx%lld sky domes) in %s\n", written.frames, written.width,
              written.height, static_cast<long long>(in.params.skyWidth),
              static_cast<long long>(in.params.skyWidth / 2), o.out.c_str());
}

}  // namespace

void addLightmap(CLI::App& app) {
  auto* cmd = app.add_subcommand(kLightmapCommand.name, kLightmapCommand.summary);
  auto o = std::make_shared<LightmapOptions>();
  auto given = std::make_shared<LightingOverrides>();
  cmd->add_option("--terrain", o->terrain.heightfield,
                  "Heightfield (single-channel; 16-bit PNG, TIFF, EXR...). Default: built-in procedural terrain");
  cmd->add_option("--bounce-albedo", o->terrain.bounceAlbedo,
                  "Colour (albedo) of the surrounding terrain for the coloured bounce light only, same size "
                  "(default: the texel's own albedo)");
  cmd->add_option("--albedo", o->terrain.albedo,
                  "Diffuse colour map, same size as the heightfield (8/16-bit = sRGB, float = linear)");
  CLI::Option* cellSize = cmd->add_option("--cell-size", o->terrain.cellSize,
                                          "Metres between heightfield samples (a DEM's own unless given)")
                              ->default_val(10.0);
  CLI::Option* verticalScale =
      cmd->add_option("--vertical-scale", o->terrain.verticalScale,
                      "Metres at full scale for integer heightfields; a multiplier for float ones and DEMs (heights "
                      "in metres are used as they are unless given)")
          ->default_val(1000.0);
  cmd->add_option("--size", o->terrain.procedural.size, "Procedural terrain size in texels")->default_val(512);
  cmd->add_option("--seed", o->terrain.procedural.seed, "Procedural terrain seed")->default_val(1);
  cmd->add_option("--relief", o->terrain.procedural.reliefMetres, "Procedural terrain relief in metres")
      ->default_val(900.0);
  cmd->add_option("--cloud-texture", o->terrain.cloudTexture,
                  "Single-channel cloud density texture (implies --clouds)");
  addLightingOptions(cmd, o->params, o->noMoon, *given, LightingOptionNames{}, [](CLI::Option*) {});
  cmd->add_option("--config", o->config, "TOML file of lighting.* parameters (command-line values win)")
      ->check(inputFile());
  cmd->add_option("--format", o->files.format,
                  "png, exr, both (png and exr), or tif (lightmaps as GeoTIFF with the DEM's georeferencing, sky "
                  "domes as exr)")
      ->default_val("png")
      ->check(oneOf("--format", {"png", "exr", "both", "tif"}));
  cmd->add_option("--debug", o->files.debug,
                  "Extra layers: horizons, sky (factor K), shadow (sun mask), nl (N.L of the key light), or all");
  cmd->add_option("--layers-format", o->files.layersFormat,
                  "Float debug layers as exr, or tif (GeoTIFF with the DEM's georeferencing)")
      ->default_val("exr")
      ->check(oneOf("--layers-format", {"exr", "tif"}));
  addThreadsOption(*cmd, o->files.threads, "Host threads that compute the lighting");
  cmd->add_option("-o,--out", o->out, "Output directory (complete or absent)")->required();
  cmd->add_flag("--force", o->force, "Replace an existing non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim lightmap --out lm/\n"
      "  vbim lightmap --size 256 --frames 24 --debug all --format both --out lm/\n");
  cmd->callback([o, given, cellSize, verticalScale] {
    o->terrain.cellSizeGiven = cellSize->count() > 0;
    o->terrain.verticalScaleGiven = verticalScale->count() > 0;
    run(*o, *given);
  });
}

}  // namespace vbim::cli
