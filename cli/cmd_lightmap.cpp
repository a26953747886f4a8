// vbim lightmap: Technique A frames (lightmaps + sky domes) from a heightfield, as image files.
#include <unistd.h>

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
#include "cli/output_dir.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/errors.hpp"
#include "lighting/fixed_angle.hpp"
#include "lighting/image_io.hpp"
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

// Prints "\rlightmap [#####.....] 12/120" on stderr, only when stderr is a terminal.
class Progress {
 public:
  explicit Progress(int total) : total_(total), enabled_(::isatty(2) == 1) {}
  void update(int done) {
    if (!enabled_) return;
    constexpr int kWidth = 40;
    const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
    std::fprintf(stderr, "\rvbim lightmap [%s%s] %d/%d frames", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), done, total_);
    if (done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  int total_;
  bool enabled_;
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
    t = readHeightfield(o.terrain, o.cellSize, o.verticalScale);
  }
  if (!o.albedo.empty()) setAlbedo(t, readColourMap(o.albedo), o.albedo);
  return t;
}

void writeDebugStatic(const DayCycleGenerator& g, const DebugLayers& d, const OutputDir& dir) {
  const Precomputed& pre = g.precomputed();
  if (d.horizons) {
    for (int k = 0; k < kDirections; ++k) {
      const std::string name = std::string("horizon_") + kDirectionNames[k];
      // The stored 16-bit codes, exactly (0 = horizontal, 65535 = 90 deg) ...
      writeGray16(dir.path(name + ".png").string(), pre.horizons.width, pre.horizons.height, pre.horizons.code[k]);
      // ... and the same in degrees for viewing.
      FloatImage deg(pre.horizons.width, pre.horizons.height, 1);
      for (std::size_t i = 0; i < deg.pixels.size(); ++i) {
        deg.pixels[i] = static_cast<float>(angleFromCode(pre.horizons.code[k][i]) * 180.0 / 3.14159265358979323846);
      }
      writeImage(dir.path(name + "_deg.exr").string(), deg);
    }
  }
  if (d.sky) {
    FloatImage k(pre.sky.width, pre.sky.height, 1);
    k.pixels = pre.sky.k;
    writeImage(dir.path("sky_factor_K.exr").string(), k);
    writeImage(dir.path("sky_factor_K.png").string(), k);
  }
}

void run(LightmapOptions& o, const std::vector<std::pair<CLI::Option*, std::function<void(DayCycleParams&)>>>& given) {
  const DebugLayers debug = parseDebug(o.debug);
  if (o.format != "png" && o.format != "exr" && o.format != "both") {
    throw Exit(2, "vbim lightmap: --format must be png, exr or both");
  }
  DayCycleParams params;
  if (!o.config.empty()) {
    ParamTable table;
    describeParams(table, params);
    table.loadTomlFile(o.config);
  }
  for (const auto& [opt, apply] : given) {
    if (opt->count() > 0) apply(params);
  }
  validateParams(params);  // before any heavy work or output
  FloatImage cloudTexture;
  if (!o.cloudTexture.empty()) {
    cloudTexture = readDensityMap(o.cloudTexture);
    params.clouds.enabled = true;
  }
  Terrain terrain = loadTerrain(o);

  OutputDir dir(o.out, o.force);
  WorkerPool pool(o.threads > 1 ? o.threads - 1 : 0);
  DayCycleGenerator gen(std::move(terrain), params, &pool, std::move(cloudTexture));
  writeDebugStatic(gen, debug, dir);

  std::ofstream csv(dir.path("frames.csv"));
  csv << "frame,hour,sun_elevation_deg,sun_azimuth_compass_deg,key_light\n";
  Progress progress(gen.frameCount());
  progress.update(0);
  FloatImage light, sky, mask;
  for (int i = 0; i < gen.frameCount(); ++i) {
    gen.renderFrame(i, light, sky, debug.shadow ? &mask : nullptr);
    const FrameLighting f = gen.frameLighting(i);
    csv << i << "," << f.hour << "," << f.sun.elevation * 180.0 / 3.14159265358979323846 << ","
        << compassDegrees(f.sun.azimuth) << "," << (f.keyIsMoon ? "moon" : "sun") << "\n";
    for (const char* ext : {".png", ".exr"}) {
      if (o.format != "both" && o.format != std::string(ext + 1)) continue;
      writeImage(dir.path(frameName("lightmap", i, ext)).string(), light);
      writeImage(dir.path(frameName("sky", i, ext)).string(), sky);
      if (debug.shadow) writeImage(dir.path(frameName("shadow", i, ext)).string(), mask);
    }
    progress.update(i + 1);
  }
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
  const DayCycleParams& p = o->params;  // defaults shown in --help
  using Apply = std::function<void(DayCycleParams&)>;
  auto given = std::make_shared<std::vector<std::pair<CLI::Option*, Apply>>>();
  // A parameter option is bound to the command line's copy of the field; `given` copies it over the
  // config file's value only when the option was given. `field` names the field in any params.
  auto param = [&](const std::string& flags, auto field, const std::string& help) {
    CLI::Option* opt = cmd->add_option(flags, field(o->params), help);
    given->push_back({opt, [o, field](DayCycleParams& dst) { field(dst) = field(o->params); }});
    return opt;
  };
  auto flag = [&](const std::string& flags, auto field, const std::string& help) {
    CLI::Option* opt = cmd->add_flag(flags, field(o->params), help);
    given->push_back({opt, [o, field](DayCycleParams& dst) { field(dst) = field(o->params); }});
  };
#define VBIM_FIELD(member)          \
  [](DayCycleParams & q) -> auto& { \
    return q.member;                \
  }
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
  param("--latitude", VBIM_FIELD(latitudeDeg), "Latitude in degrees, -90..90")->default_val(p.latitudeDeg);
  param("--day", VBIM_FIELD(dayOfYear), "Day of the year, 1..366")->default_val(p.dayOfYear);
  param("--start-hour", VBIM_FIELD(startHour), "Local solar time of the first frame")->default_val(p.startHour);
  param("--end-hour", VBIM_FIELD(endHour), "Local solar time of the last frame (0 to 24 loops a day)")
      ->default_val(p.endHour);
  param("--frames", VBIM_FIELD(frames), "Number of frames")->default_val(p.frames);
  param("--sun-diameter", VBIM_FIELD(sunDiameterDeg), "Sun's angular diameter in degrees (larger = softer shadows)")
      ->default_val(p.sunDiameterDeg);
  flag("--exact-disc", VBIM_FIELD(exactDisc),
       "Occlude the sun by visible disc area instead of the article's linear ramp");
  param("--turbidity", VBIM_FIELD(turbidity), "Atmospheric turbidity (Preetham; 2-6)")->default_val(p.turbidity);
  param("--sky-patches", VBIM_FIELD(skyPatches), "Sky patches, 1..8")->default_val(p.skyPatches);
  param("--exposure", VBIM_FIELD(exposureKlux), "Irradiance in klux that maps to 1.0")->default_val(p.exposureKlux);
  flag("--multiply-albedo", VBIM_FIELD(multiplyAlbedo),
       "Multiply the lightmap by the colour map (as the article does)");
  param("--sky-width", VBIM_FIELD(skyWidth), "Sky dome image width (height = width / 2)")->default_val(p.skyWidth);
  flag("--clouds", VBIM_FIELD(clouds.enabled), "Moving procedural cloud shadows");
  param("--cloud-coverage", VBIM_FIELD(clouds.coverage), "Cloud coverage 0..1")->default_val(p.clouds.coverage);
  cmd->add_option("--cloud-texture", o->cloudTexture, "Single-channel cloud density texture (implies --clouds)");
  CLI::Option* noMoon = cmd->add_flag("--no-moon", o->noMoon, "No moonlight at night");
  given->push_back({noMoon, [o](DayCycleParams& dst) { dst.moon = !o->noMoon; }});
  cmd->add_option("--config", o->config, "TOML file of lighting.* parameters (command-line values win)");
  cmd->add_option("--format", o->format, "png, exr or both")->default_val("png");
  cmd->add_option("--debug", o->debug, "Extra layers: horizons, sky (factor K), shadow (sun mask), or all");
  cmd->add_option("--threads", o->threads, "Host threads (the output does not depend on it)")->default_val(2);
  cmd->add_option("--out", o->out, "Output directory (complete or absent)")->required();
  cmd->add_flag("--force", o->force, "Replace an existing non-empty output directory");
#undef VBIM_FIELD
  cmd->callback([o, given] {
    try {
      run(*o, *given);
    } catch (const LightingError& e) {
      throw Exit(2, std::string("vbim lightmap: ") + e.what());
    } catch (const ConfigError& e) {
      throw Exit(2, std::string("vbim lightmap: ") + e.what());
    }
  });
}

}  // namespace vbim::cli
