#include "lighting/lightmap_files.hpp"

#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

#include "imageio/image_writer.hpp"
#include "lighting/error.hpp"
#include "lighting/fixed_angle.hpp"
#include "lighting/geotiff_layers.hpp"
#include "lighting/image_files.hpp"
#include "lighting/sun_position.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr double kPi = 3.14159265358979323846;

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
      throw LightingError("--debug: unknown layer '" + item + "'; expected horizons, sky, shadow, nl or all");
    }
  }
  return d;
}

// A float layer as `stem`.exr, or as `stem`.tif with the terrain's georeferencing.
struct LayerWriter {
  const std::filesystem::path& dir;
  bool geotiff;
  const Georeference& geo;
  void operator()(const std::string& stem, const FloatImage& image, const std::string& description) const {
    if (geotiff) {
      writeGeoTiff(dir / (stem + ".tif"), image, geo, description);
    } else {
      writeImage(dir / (stem + ".exr"), image);
    }
  }
};

void writeDebugStatic(const DayCycleGenerator& g, const DebugLayers& d, const std::filesystem::path& dir,
                      const LayerWriter& layer) {
  const Precomputed& pre = g.precomputed();
  if (d.horizons) {
    for (int k = 0; k < kDirections; ++k) {
      const std::string name = std::string("horizon_") + kDirectionNames[k];
      // The stored 16-bit codes, exactly (0 = horizontal, 65535 = 90 deg) ...
      imageio::writeImage(
          dir / (name + ".png"),
          imageio::ImageView<std::uint16_t>{pre.horizons.width, pre.horizons.height, 1, pre.horizons.code[k].data()});
      // ... and the same in degrees for viewing.
      FloatImage deg(pre.horizons.width, pre.horizons.height, 1);
      for (std::size_t i = 0; i < deg.pixels.size(); ++i) {
        deg.pixels[i] = static_cast<float>(angleFromCode(pre.horizons.code[k][i]) * 180.0 / kPi);
      }
      layer(name + "_deg", deg, std::string("horizon elevation towards ") + kDirectionNames[k] + " (degrees)");
    }
  }
  if (d.sky) {
    FloatImage k(pre.sky.width, pre.sky.height, 1);
    k.pixels = pre.sky.k;
    layer("sky_factor_K", k, "sky view factor K");
    writeImage(dir / "sky_factor_K.png", k);
  }
}

}  // namespace

void checkLightmapRequest(const LightmapFilesRequest& r) {
  parseDebug(r.debug);
  if (r.format != "png" && r.format != "exr" && r.format != "both" && r.format != "tif") {
    throw LightingError("--format must be png, exr, tif or both");
  }
  if (r.layersFormat != "exr" && r.layersFormat != "tif") throw LightingError("--layers-format must be exr or tif");
}

LightmapFiles writeLightmapFiles(const LightmapFilesRequest& r, TerrainFile terrain, const DayCycleParams& params,
                                 FloatImage cloudTexture, const std::filesystem::path& dir,
                                 const std::function<void(int, int)>& progress) {
  checkLightmapRequest(r);
  const DebugLayers debug = parseDebug(r.debug);
  WorkerPool pool(r.threads > 1 ? r.threads - 1 : 0);
  DayCycleGenerator gen(std::move(terrain.terrain), params, &pool, std::move(cloudTexture));
  const LayerWriter layer{dir, r.layersFormat == "tif", terrain.geo};
  writeDebugStatic(gen, debug, dir, layer);

  std::ofstream csv(dir / "frames.csv");
  csv << "frame,hour,sun_elevation_deg,sun_azimuth_compass_deg,key_light\n";
  progress(0, gen.frameCount());
  FloatImage light, sky, mask, cosine;
  for (int i = 0; i < gen.frameCount(); ++i) {
    gen.renderFrame(i, light, sky, debug.shadow ? &mask : nullptr);
    const FrameLighting f = gen.frameLighting(i);
    csv << i << "," << f.hour << "," << f.sun.elevation * 180.0 / kPi << "," << compassDegrees(f.sun.azimuth) << ","
        << (f.keyIsMoon ? "moon" : "sun") << "\n";
    if (r.format == "tif") {
      // Lightmaps on the map, georeferenced; the sky dome is not on the ground: EXR.
      writeGeoTiff(dir / frameName("lightmap", i, ".tif"), light, terrain.geo, "lightmap (1.0 = exposure)");
      writeImage(dir / frameName("sky", i, ".exr"), sky);
    }
    for (const char* ext : {".png", ".exr"}) {
      if (r.format != "both" && r.format != std::string(ext + 1)) continue;
      writeImage(dir / frameName("lightmap", i, ext), light);
      writeImage(dir / frameName("sky", i, ext), sky);
      if (debug.shadow && !layer.geotiff) writeImage(dir / frameName("shadow", i, ext), mask);
    }
    if (debug.shadow && (layer.geotiff || r.format == "tif")) {
      layer(frameName("shadow", i, ""), mask, "sun visibility (shadow mask)");
    }
    if (debug.cosine) {
      cosineLayer(gen.precomputed(), f.key.direction, cosine);
      layer(frameName("nl", i, ""), cosine, "N.L, cosine of the key light on the terrain normal");
    }
    progress(i + 1, gen.frameCount());
  }
  csv.close();
  if (!csv) throw LightingError((dir / "frames.csv").string() + ": cannot write the frame list");
  return {gen.frameCount(), gen.precomputed().terrain.width, gen.precomputed().terrain.height};
}

}  // namespace vbim::lighting
