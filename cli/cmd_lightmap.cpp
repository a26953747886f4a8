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
#include "cli/output_dir.hpp"
#include "cli/progress.hpp"
#include "config/params_toml.hpp"
#include "imageio/error.hpp"
#include "imageio/image_writer.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/error.hpp"
#include "lighting/fixed_angle.hpp"
#include "lighting/image_files.hpp"
#include "lighting/procedural_terrain.hpp"
#include "runtime/params.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::lighting;

struct LightmapOptions {
  std::string terrain, albedo, cloudTexture, config, out, format = "png", debug;
  double cellSize = 10.0, verticalScale = 1000.0, relief = 900.0;
  std::int64_t size = 512, seed = 1;
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
  bool horizons = false, sky = false, shadow = false;
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
    } else if (item == "all") {
      d = {true, true, true};
    } else if (!item.empty()) {
      throw Exit(2, "vbim lightmap: --debug: unknown layer '" + item + "'; expected horizons, sky, shadow or all");
    }
  }
  return d;
}

Terrain loadTerrain(const LightmapOptions& o) {
  Terrain t;
  if (o.terrain.empty()) {
    t = proceduralTerrain({.size = o.size, .cellSize = o.cellSize, .reliefMetres = o.relief, .seed = o.seed});
    if (o.albedo.empty()) setAlbedo(t, proceduralAlbedo(t), "procedural albedo");
  } else {
    t = lighting::readHeightfield(o.terrain, o.cellSize, o.verticalScale);
  }
  if (!o.albedo.empty()) setAlbedo(t, lighting::readColourMap(o.albedo), o.albedo);
  return t;
}

void writeDebugStatic(const DayCycleGenerator& g, const DebugLayers& d, const OutputDir& dir) {
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
      lighting::writeImage(dir.path(name + "_deg.exr"), deg);
    }
  }
  if (d.sky) {
    FloatImage k(pre.sky.width, pre.sky.height, 1);
    k.pixels = pre.sky.k;
    lighting::writeImage(dir.path("sky_factor_K.exr"), k);
    lighting::writeImage(dir.path("sky_factor_K.png"), k);
  }
}

void run(LightmapOptions& o, const LightingOverrides& given) {
  const DebugLayers debug = parseDebug(o.debug);
  if (o.format != "png" && o.format != "exr" && o.format != "both") {
    throw Exit(2, "vbim lightmap: --format must be png, exr or both");
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
  if (!o.cloudTexture.empty()) {
    cloudTexture = lighting::readDensityMap(o.cloudTexture);
    params.clouds.enabled = true;
  }
  Terrain terrain = loadTerrain(o);

  OutputDir dir(o.out, o.force);
  WorkerPool pool(o.threads > 1 ? o.threads - 1 : 0);
  DayCycleGenerator gen(std::move(terrain), params, &pool, std::move(cloudTexture));
  writeDebugStatic(gen, debug, dir);

  std::ofstream csv(dir.path("frames.csv"));
  csv << "frame,hour,sun_elevation_deg,sun_azimuth_compass_deg,key_light\n";
  Progress progress("vbim lightmap", "frames");
  progress.show(0, gen.frameCount());
  FloatImage light, sky, mask;
  for (int i = 0; i < gen.frameCount(); ++i) {
    gen.renderFrame(i, light, sky, debug.shadow ? &mask : nullptr);
    const FrameLighting f = gen.frameLighting(i);
    csv << i << "," << f.hour << "," << f.sun.elevation * 180.0 / 3.14159265358979323846 << ","
        << compassDegrees(f.sun.azimuth) << "," << (f.keyIsMoon ? "moon" : "sun") << "\n";
    for (const char* ext : {".png", ".exr"}) {
      if (o.format != "both" && o.format != std::string(ext + 1)) continue;
      lighting::writeImage(dir.path(frameName("lightmap", i, ext)), light);
      lighting::writeImage(dir.path(frameName("sky", i, ext)), sky);
      if (debug.shadow) lighting::writeImage(dir.path(frameName("shadow", i, ext)), mask);
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
  cmd->add_option("--terrain", o->terrain,
                  "Heightfield (single-channel; 16-bit PNG, TIFF, EXR...). Default: built-in procedural terrain");
  cmd->add_option("--albedo", o->albedo,
                  "Diffuse colour map, same size as the heightfield (8/16-bit = sRGB, float = linear)");
  cmd->add_option("--cell-size", o->cellSize, "Metres between heightfield samples")->default_val(10.0);
  cmd->add_option("--vertical-scale", o->verticalScale,
                  "Metres at full scale for integer heightfields; metres per unit for float ones")
      ->default_val(1000.0);
  cmd->add_option("--size", o->size, "Procedural terrain size in texels")->default_val(512);
  cmd->add_option("--seed", o->seed, "Procedural terrain seed")->default_val(1);
  cmd->add_option("--relief", o->relief, "Procedural terrain relief in metres")->default_val(900.0);
  cmd->add_option("--cloud-texture", o->cloudTexture, "Single-channel cloud density texture (implies --clouds)");
  addLightingOptions(cmd, o->params, o->noMoon, *given, LightingOptionNames{}, [](CLI::Option*) {});
  cmd->add_option("--config", o->config, "TOML file of lighting.* parameters (command-line values win)");
  cmd->add_option("--format", o->format, "png, exr or both")->default_val("png");
  cmd->add_option("--debug", o->debug, "Extra layers: horizons, sky (factor K), shadow (sun mask), or all");
  cmd->add_option("--threads", o->threads, "Host threads (the output does not depend on it)")
      ->default_val(2)
      ->check(hostThreads());
  cmd->add_option("--out", o->out, "Output directory (complete or absent)")->required();
  cmd->add_flag("--force", o->force, "Replace an existing non-empty output directory");
  cmd->callback([o, given] {
    try {
      run(*o, *given);
    } catch (const LightingError& e) {
      throw Exit(2, std::string("vbim lightmap: ") + e.what());
    } catch (const imageio::ImageIoError& e) {
      throw Exit(2, std::string("vbim lightmap: ") + e.what());
    } catch (const ConfigError& e) {
      throw Exit(2, std::string("vbim lightmap: ") + e.what());
    }
  });
}

}  // namespace vbim::cli
