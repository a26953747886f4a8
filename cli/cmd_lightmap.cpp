// vbim lightmap: Technique A frames (lightmaps + sky domes) from a heightfield, as image files.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>
#include <thread>
#include <vector>

#include "cli/command.hpp"
#include "cli/host_threads.hpp"
#include "cli/lighting_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/progress.hpp"
#include "config/params_toml.hpp"
#include "imageio/error.hpp"
#include "imageio/image_writer.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/error.hpp"
#include "lighting/fixed_angle.hpp"
#include "lighting/geotiff_layers.hpp"
#include "lighting/image_files.hpp"
#include "lighting/terrain_file.hpp"
#include "runtime/params.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::lighting;

struct LightmapOptions {
  TerrainSource terrain;  // its *Given flags set after parsing: overrides for a DEM
  std::string config, out, format = "png", debug, layersFormat = "exr";
  unsigned threads = 2;
  bool force = false, noMoon = false;
  DayCycleParams params;  // values given on the command line
};

std::string frameName(const std::string& stem, int i, const std::string& ext) {
  std::ostringstream s;
  s << stem << "_" << std::setw(4) << std::setfill('0') << i << ext;
  return s.str();
}

struct DebugLayers {
  bool horizons = false, sky = false, shadow = false, cosine = false;
};

DebugLayers parseDebug(const std::string& list) {
  DebugLayers d;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item == "horizons") {
      d.horizons = true;
    } else if (item == "sky") {
      d.sky = true;
    } else if (item == "shadow") {
      d.shadow = true;
    } else if (item == "nl") {
      d.cosine = true;
    } else if (item == "all") {
      d = {true, true, true, true};
    } else if (!item.empty()) {
      throw Exit(2, "--debug: unknown layer '" + item + "'; expected horizons, sky, shadow, nl or all");
    }
  }
  return d;
}

// A float layer as `stem`.exr, or as `stem`.tif with the terrain's georeferencing.
struct LayerWriter {
  const OutputDir& dir;
  bool geotiff;
  const Georeference& geo;
  void operator()(const std::string& stem, const FloatImage& image, const std::string& description) const {
    if (geotiff) {
      writeGeoTiff(dir.path(stem + ".tif"), image, geo, description);
    } else {
      lighting::writeImage(dir.path(stem + ".exr"), image);
    }
  }
};

void writeDebugStatic(const DayCycleGenerator& g, const DebugLayers& d, const OutputDir& dir,
                      const LayerWriter& layer) {
  const Precomputed& pre = g.precomputed();
  if (d.horizons) {
    for (int k = 0; k < kDirections; ++k) {
      const std::string name = std::string("horizon_") + kDirectionNames[k];
      // The stored 16-bit codes, exactly (0 = horizontal, 65535 = 90 deg) ...
      imageio::writeImage(
          dir.path(name + ".png"),
          imageio::ImageView<std::uint16_t>{pre.horizons.width, pre.horizons.height, 1, pre.horizons.code[k].data()});
      // ... and the same in degrees for viewing.
      FloatImage deg(pre.horizons.width, pre.horizons.height, 1);
      for (std::size_t i = 0; i < deg.pixels.size(); ++i) {
        deg.pixels[i] = static_cast<float>(angleFromCode(pre.horizons.code[k][i]) * 180.0 / 3.14159265358979323846);
      }
      layer(name + "_deg", deg, std::string("horizon elevation towards ") + kDirectionNames[k] + " (degrees)");
    }
  }
  if (d.sky) {
    FloatImage k(pre.sky.width, pre.sky.height, 1);
    k.pixels = pre.sky.k;
    layer("sky_factor_K", k, "sky view factor K");
    lighting::writeImage(dir.path("sky_factor_K.png"), k);
  }
}

void run(LightmapOptions& o, const LightingOverrides& given) {
  const DebugLayers debug = parseDebug(o.debug);
  if (o.format != "png" && o.format != "exr" && o.format != "both" && o.format != "tif") {
    throw Exit(2, "--format must be png, exr, tif or both");
  }
  if (o.layersFormat != "exr" && o.layersFormat != "tif") {
    throw Exit(2, "--layers-format must be exr or tif");
  }
  DayCycleParams params;
  if (!o.config.empty()) {
    ParamTable table;
    describeParams(table, params);
    config::applyTomlFile(table, o.config);
  }
  applyGivenLightingOptions(given, params);
  validateParams(params);  // before any heavy work or output
  FloatImage cloudTexture;
  if (!o.terrain.cloudTexture.empty()) {
    cloudTexture = lighting::readDensityMap(o.terrain.cloudTexture);
    params.clouds.enabled = true;
  }
  o.terrain.procedural.cellSize = o.terrain.cellSize;
  TerrainFile terrain = loadTerrainAsIs(o.terrain);
  for (const std::string& note : terrain.notes)
    std::printf("vbim lightmap: %s: %s\n", o.terrain.heightfield.c_str(), note.c_str());

  OutputDir dir(o.out, o.force);
  WorkerPool pool(o.threads > 1 ? o.threads - 1 : 0);
  DayCycleGenerator gen(std::move(terrain.terrain), params, &pool, std::move(cloudTexture));
  const LayerWriter layer{dir, o.layersFormat == "tif", terrain.geo};
  writeDebugStatic(gen, debug, dir, layer);

  std::ofstream csv(dir.path("frames.csv"));
  csv << "frame,hour,sun_elevation_deg,sun_azimuth_compass_deg,key_light\n";
  Progress progress("vbim lightmap", "frames");
  progress.show(0, gen.frameCount());
  FloatImage light, sky, mask, cosine;
  for (int i = 0; i < gen.frameCount(); ++i) {
    gen.renderFrame(i, light, sky, debug.shadow ? &mask : nullptr);
    const FrameLighting f = gen.frameLighting(i);
    csv << i << "," << f.hour << "," << f.sun.elevation * 180.0 / 3.14159265358979323846 << ","
        << compassDegrees(f.sun.azimuth) << "," << (f.keyIsMoon ? "moon" : "sun") << "\n";
    if (o.format == "tif") {
      // Lightmaps on the map, georeferenced; the sky dome is not on the ground: EXR.
      writeGeoTiff(dir.path(frameName("lightmap", i, ".tif")), light, terrain.geo, "lightmap (1.0 = exposure)");
      lighting::writeImage(dir.path(frameName("sky", i, ".exr")), sky);
    }
    for (const char* ext : {".png", ".exr"}) {
      if (o.format != "both" && o.format != std::string(ext + 1)) continue;
      lighting::writeImage(dir.path(frameName("lightmap", i, ext)), light);
      lighting::writeImage(dir.path(frameName("sky", i, ext)), sky);
      if (debug.shadow && !layer.geotiff) lighting::writeImage(dir.path(frameName("shadow", i, ext)), mask);
    }
    if (debug.shadow && (layer.geotiff || o.format == "tif")) {
      layer(frameName("shadow", i, ""), mask, "sun visibility (shadow mask)");
    }
    if (debug.cosine) {
      cosineLayer(gen.precomputed(), f.key.direction, cosine);
      layer(frameName("nl", i, ""), cosine, "N.L, cosine of the key light on the terrain normal");
    }
    progress.show(i + 1, gen.frameCount());
  }
  progress.finish();
  csv.close();
  if (!csv) throw Exit(2, dir.path("frames.csv").string() + ": cannot write the frame list");
  dir.commit();
  std::printf("vbim lightmap: %d frames (%dx%d lightmaps, %lldx%lld sky domes) in %s\n", gen.frameCount(),
              gen.precomputed().terrain.width, gen.precomputed().terrain.height,
              static_cast<long long>(params.skyWidth), static_cast<long long>(params.skyWidth / 2), o.out.c_str());
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
  cmd->add_option("--format", o->format,
                  "png, exr, both (png and exr), or tif (lightmaps as GeoTIFF with the DEM's georeferencing, sky "
                  "domes as exr)")
      ->default_val("png");
  cmd->add_option("--debug", o->debug,
                  "Extra layers: horizons, sky (factor K), shadow (sun mask), nl (N.L of the key light), or all");
  cmd->add_option("--layers-format", o->layersFormat,
                  "Float debug layers as exr, or tif (GeoTIFF with the DEM's georeferencing)")
      ->default_val("exr");
  cmd->add_option("--threads", o->threads, "Host threads (the output does not depend on it)")
      ->default_val(2)
      ->check(hostThreads());
  cmd->add_option("--out", o->out, "Output directory (complete or absent)")->required();
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
