#include "lighting/authoring/technique_a_stream.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <sstream>

#include "config/params_toml.hpp"
#include "imageio/error.hpp"
#include "lighting/authoring/technique_a_record.hpp"
#include "lighting/error.hpp"
#include "lighting/image_files.hpp"
#include "lighting/terrain_file.hpp"
#include "runtime/param_table.hpp"
#include "runtime/worker_pool.hpp"
#include "streams/authoring/error.hpp"
#include "streams/record_packs.hpp"

namespace vbim::lighting {

namespace {

using streams::AuthoringError;

// The overcast preset (see the header): cloud shadows over most of the ground, a hazy atmosphere
// (the top of Preetham's fitted range: higher turbidities brighten the sky instead of dimming it),
// less direct sun, and everything dimmer through a higher exposure normalisation. Assumption: an
// artistic stand-in, not a radiative model of overcast skies.
constexpr double kOvercastCoverage = 0.85;
constexpr double kOvercastOpacity = 0.8;
constexpr double kOvercastTurbidity = 6.0;
constexpr double kOvercastSunFactor = 0.4;
constexpr double kOvercastExposureFactor = 1.6;

// A frame side the MPEG-2 encoder and the IPU take: a whole number of 16x16 macroblocks, at most
// the 12-bit size field without extensions.
void checkSide(int side, const std::string& what) {
  if (side <= 0 || side % 16 != 0 || side > streams::kMaxFrameSide) {
    throw AuthoringError(what + " is " + std::to_string(side) +
                         " texels; a stream frame side must be a multiple of 16 (" + "whole macroblocks) from 16 to " +
                         std::to_string(streams::kMaxFrameSide));
  }
}

}  // namespace

std::vector<WeatherVariant> weatherVariants(const std::string& list, const DayCycleParams& base) {
  std::vector<WeatherVariant> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) {
      out.push_back(weatherVariant(item, base));
      continue;
    }
    if (eq == 0 || eq + 1 == item.size())
      throw streams::AuthoringError("--weather '" + item + "': expected a preset name or NAME=FILE.toml");
    WeatherVariant v{item.substr(0, eq), base};
    ParamTable table;
    describeParams(table, v.params);
    config::applyTomlFile(table, item.substr(eq + 1));
    out.push_back(std::move(v));
  }
  if (out.empty()) throw streams::AuthoringError("--weather names no variant");
  return out;
}

const std::vector<std::string>& weatherPresetNames() {
  static const std::vector<std::string> names{"clear", "overcast"};
  return names;
}

WeatherVariant weatherVariant(const std::string& name, const DayCycleParams& base) {
  WeatherVariant v{name, base};
  if (name == "clear") return v;
  if (name == "overcast") {
    v.params.clouds.enabled = true;
    v.params.clouds.coverage = kOvercastCoverage;
    v.params.clouds.opacity = kOvercastOpacity;
    v.params.turbidity = std::max(base.turbidity, kOvercastTurbidity);
    v.params.sunKlux = base.sunKlux * kOvercastSunFactor;
    v.params.exposureKlux = base.exposureKlux * kOvercastExposureFactor;
    return v;
  }
  std::string known;
  for (const std::string& n : weatherPresetNames()) known += (known.empty() ? "" : ", ") + n;
  throw AuthoringError("unknown weather '" + name + "'; expected one of " + known + " (or NAME=FILE.toml)");
}

namespace {

// A colour map on the terrain's grid: as it is when it has the terrain's size; on the heightfield
// file's grid, carried through the same flips, resampling, crop or pad (`toFile`); refused otherwise.
FloatImage colourMapOnTerrain(const std::string& path, const Terrain& t, int fileWidth, int fileHeight,
                              const GridMapping& toFile, std::vector<std::string>& notes) {
  FloatImage map = readColourMap(path);
  if (map.width == t.width && map.height == t.height) return map;
  auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
  if (map.width == fileWidth && map.height == fileHeight) {
    notes.push_back(path + ": " + size(map.width, map.height) +
                    " on the heightfield file's grid, resampled with it to " + size(t.width, t.height));
    return resampleImage(map, toFile, t.width, t.height);
  }
  throw LightingError(path + ": colour map is " + size(map.width, map.height) + "; expected the terrain's size " +
                      size(t.width, t.height) + " or the heightfield file's " + size(fileWidth, fileHeight));
}

}  // namespace

Terrain loadTerrain(const TerrainSource& src, std::vector<std::string>* notesOut) {
  std::vector<std::string> notes;
  try {
    Terrain t;
    int fileWidth = 0, fileHeight = 0;
    GridMapping toFile;
    if (src.heightfield.empty()) {
      t = proceduralTerrain(src.procedural);
      if (src.albedo.empty()) setAlbedo(t, proceduralAlbedo(t), "procedural albedo");
      fileWidth = t.width;
      fileHeight = t.height;
    } else {
      TerrainFileOptions options;
      options.pictureCellSize = src.cellSize;  // pictures keep these as they always did
      options.pictureFullScale = src.verticalScale;
      if (src.cellSizeGiven) options.cellSize = src.cellSize;
      if (src.verticalScaleGiven) options.verticalScale = src.verticalScale;
      TerrainFile file = loadTerrainFile(src.heightfield, options);
      t = std::move(file.terrain);
      notes = std::move(file.notes);
      fileWidth = file.fileWidth;
      fileHeight = file.fileHeight;
      toFile = file.toFile;
    }
    const std::string origin = src.heightfield.empty() ? "procedural terrain" : src.heightfield;
    const GridWindow window = fitWindow(t.width, t.height, src.fit, origin);
    if (window.width != t.width || window.height != t.height) {
      const bool crop = src.fit == TerrainFit::Crop;
      notes.push_back(std::string(crop ? "cropped" : "padded") + " from " + std::to_string(t.width) + "x" +
                      std::to_string(t.height) + " to " + std::to_string(window.width) + "x" +
                      std::to_string(window.height) + " texels (whole 16x16 macroblocks), centred: " +
                      (crop ? "first kept texel (" : "the heightfield starts at texel (") +
                      std::to_string(crop ? window.x0 : -window.x0) + ", " +
                      std::to_string(crop ? window.y0 : -window.y0) + ")" +
                      (crop ? "" : ", the edges repeated outwards") + "; --terrain-fit " + (crop ? "pad" : "crop") +
                      " or none for the other choices");
      t = windowTerrain(t, window);
      toFile = windowMapping(toFile, window);
    }
    if (!src.albedo.empty()) {
      setAlbedo(t, colourMapOnTerrain(src.albedo, t, fileWidth, fileHeight, toFile, notes), src.albedo);
    }
    if (!src.bounceAlbedo.empty()) {
      setBounceAlbedo(t, colourMapOnTerrain(src.bounceAlbedo, t, fileWidth, fileHeight, toFile, notes),
                      src.bounceAlbedo);
    }
    if (notesOut != nullptr) *notesOut = std::move(notes);
    return t;
  } catch (const LightingError& e) {
    throw AuthoringError(e.what());
  } catch (const imageio::ImageIoError& e) {
    throw AuthoringError(e.what());
  }
}

void checkStreamSettings(const TechniqueAStreamSettings& s, int terrainWidth, int terrainHeight,
                         const std::string& terrainOrigin) {
  checkSide(terrainWidth, terrainOrigin + ": width");
  checkSide(terrainHeight, terrainOrigin + ": height");
  std::vector<WeatherVariant> variants = s.variants;
  if (variants.empty()) variants.push_back(weatherVariant("clear", s.base));
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const WeatherVariant& v = variants[i];
    const std::string who = "variant '" + v.name + "': ";
    if (v.name.empty() || v.name.size() > streams::Descriptor::kMaxVariantName) {
      throw AuthoringError(who + "a variant name must have 1 to " +
                           std::to_string(streams::Descriptor::kMaxVariantName) + " bytes");
    }
    for (std::size_t j = 0; j < i; ++j)
      if (variants[j].name == v.name) throw AuthoringError(who + "the name is given twice");
    try {
      validateParams(v.params);
    } catch (const LightingError& e) {
      throw AuthoringError(who + e.what());
    }
    checkSide(static_cast<int>(v.params.skyWidth), who + "lighting.sky_width");
    checkSide(static_cast<int>(v.params.skyWidth / 2), who + "the sky height (lighting.sky_width / 2)");
    const WeatherVariant& first = variants.front();
    if (v.params.frames != first.params.frames) {
      throw AuthoringError(who + "lighting.frames = " + std::to_string(v.params.frames) + " but variant '" +
                           first.name + "' has " + std::to_string(first.params.frames) +
                           " (variants need equal lengths to branch)");
    }
    if (v.params.skyWidth != first.params.skyWidth) {
      throw AuthoringError(who + "lighting.sky_width = " + std::to_string(v.params.skyWidth) + " but variant '" +
                           first.name + "' has " + std::to_string(first.params.skyWidth) +
                           " (one sky size per stream)");
    }
  }
}

Rgba8Image streamFrame(const FloatImage& image, const streams::ToneMapping& tone) {
  streams::FloatRgbImage rgb(image.width, image.height);
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c)
      rgb.rgb[i * 3 + c] = image.pixels[i * image.channels + (image.channels >= 3 ? c : 0)];
  }
  return streams::toneMap(rgb, tone);
}

AuthoredStream authorTechniqueAStream(const TechniqueAStreamSettings& s, const TechniqueAProgressFn& progress) {
  streams::quietLibavLog();
  std::vector<WeatherVariant> variants = s.variants;
  if (variants.empty()) variants.push_back(weatherVariant("clear", s.base));
  // Cheap checks first (settings), then the terrain file, then its size: nothing heavy runs on a
  // setting that would fail later.
  for (const WeatherVariant& v : variants) {
    try {
      validateParams(v.params);
    } catch (const LightingError& e) {
      throw AuthoringError("variant '" + v.name + "': " + e.what());
    }
  }
  std::vector<std::string> terrainNotes;
  const Terrain terrain = loadTerrain(s.terrain, &terrainNotes);
  const std::string origin = s.terrain.heightfield.empty() ? "procedural terrain" : s.terrain.heightfield;
  checkStreamSettings(s, terrain.width, terrain.height, origin);
  FloatImage cloudTexture;
  if (!s.terrain.cloudTexture.empty()) {
    try {
      cloudTexture = lighting::readDensityMap(s.terrain.cloudTexture);
    } catch (const LightingError& e) {
      throw AuthoringError(e.what());
    } catch (const imageio::ImageIoError& e) {
      throw AuthoringError(e.what());
    }
  }

  streams::AuthorSettings settings = s.stream;
  settings.withSky = true;
  streams::StreamWriter writer(settings);
  std::optional<WorkerPool> pool;
  if (s.threads > 1) pool.emplace(s.threads - 1);
  WorkerPool* poolPtr = pool ? &*pool : nullptr;

  TechniqueAProgress p;
  p.total = static_cast<int>(variants.size() * static_cast<std::size_t>(variants.front().params.frames));
  FloatImage light, sky;
  try {
    for (WeatherVariant& v : variants) {
      if (!cloudTexture.empty()) v.params.clouds.enabled = true;
      DayCycleGenerator gen(terrain, v.params, poolPtr, cloudTexture);
      writer.beginVariant(v.name);
      for (int f = 0; f < gen.frameCount(); ++f) {
        gen.renderFrame(f, light, sky);
        const Rgba8Image lm = streamFrame(light, s.tone), skyFrame = streamFrame(sky, s.tone);
        writer.addFrame(lm, &skyFrame);
        ++p.done;
        p.variant = v.name;
        p.frame = f;
        if (progress) progress(p);
      }
    }
  } catch (const LightingError& e) {
    throw AuthoringError(e.what());
  }
  AuthoredStream out;
  out.bytes = writer.finish();
  // How it was made, after the last video sector: players never read it (streams/record_packs.hpp).
  streams::appendAuthoringRecord(out.bytes, authoringRecordJson(s, variants, terrain));
  out.descriptor = writer.descriptor();
  out.maxQscaleUsed = writer.maxQscaleUsed();
  out.containerStretch = writer.containerStretch();
  out.terrainNotes = std::move(terrainNotes);
  return out;
}

AuthoredStream authorTechniqueA(const TechniqueAStreamSettings& s, const std::filesystem::path& out,
                                const TechniqueAProgressFn& progress) {
  AuthoredStream stream = authorTechniqueAStream(s, progress);
  streams::writeStreamFile(out, stream.bytes);
  return stream;
}

}  // namespace vbim::lighting
