#include "lighting/day_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "lighting/azimuth_sweep.hpp"
#include "lighting/error.hpp"
#include "lighting/ray_sweep.hpp"
#include "lighting/sky_model.hpp"
#include "runtime/param_table.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr int kRowBlock = 8;
constexpr int kCloudChunk = 256;  // texels of cloud transmittance computed ahead

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Daylight fades out between +2 and -6 degrees of sun elevation (civil twilight ends at -6 deg);
// the Preetham model is invalid at and below the horizon (Zotti et al. 2007), so it is evaluated
// at 2 degrees or more and scaled by this weight.
constexpr double kDayFullDeg = 2.0;
constexpr double kNightDeg = -6.0;

// Moonlight colour: a slight blue shift, the usual night tone-mapping choice (Jensen et al. 2001).
constexpr std::array<double, 3> kMoonColour{0.80, 0.90, 1.0};

Dir3 directionAt(double elevation, double azimuth) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

SunPosition positionOf(const Dir3& d) {
  SunPosition s;
  s.direction = d;
  s.elevation = std::asin(std::clamp(d.z, -1.0, 1.0));
  s.azimuth = std::atan2(d.y, d.x);
  return s;
}

}  // namespace

void describeParams(ParamTable& t, DayCycleParams& p) {
  const std::string user = "user choice";
  t.addReal("lighting.latitude_deg", &p.latitudeDeg, -90, 90, "deg", "user choice; default a mid-latitude (45 N)");
  t.addInt("lighting.day_of_year", &p.dayOfYear, 1, 366, "day", "user choice; default 172 = 21 June");
  t.addReal("lighting.start_hour", &p.startHour, 0, 24, "h", "local solar time of the first frame");
  t.addReal("lighting.end_hour", &p.endHour, 0, 24, "h",
            "local solar time of the last frame (0 to 24 loops a whole day)");
  t.addInt("lighting.frames", &p.frames, 1, 1000000, "frames", user);
  t.addBool("lighting.fixed_sun", &p.fixedSun,
            "true: the sun at sun_azimuth_deg / sun_elevation_deg in every frame instead of latitude, day and hour");
  t.addReal("lighting.sun_azimuth_deg", &p.sunAzimuthDeg, 0, 360, "deg",
            "compass: 0 = north, 90 = east, clockwise (with fixed_sun)");
  t.addReal("lighting.sun_elevation_deg", &p.sunElevationDeg, -90, 90, "deg", "above the horizontal (with fixed_sun)");
  t.addReal("lighting.sun_diameter_deg", &p.sunDiameterDeg, 0.01, 20, "deg",
            "real sun 0.53 deg; larger gives softer, anti-aliased shadow edges (Hoffman & Mitchell 2001)");
  t.addBool("lighting.exact_disc", &p.exactDisc,
            "false: the article's linear ramp; true: visible disc area (docs/lighting.md#sun-disc)");
  t.addBool("lighting.shadow_rays", &p.shadowRays,
            "true: shadows along each texel's own ray; false: its sheared sweep line "
            "(docs/lighting.md#shadows-at-any-azimuth)");
  t.addReal("lighting.turbidity", &p.turbidity, 1.7, 10, "", "Preetham et al. 1999 (fitted for 2-6; 3 = clear)");
  t.addInt("lighting.sky_patches", &p.skyPatches, 1, kMaxSkyPatches, "patches",
           "Hoffman & Mitchell: one or two patches suffice; sectors i*P/8");
  t.addInt("lighting.sky_directions", &p.skyDirections, 8, 32, "directions",
           "sky-factor sectors: 8 (Hoffman & Mitchell), 16 or 32 (docs/lighting.md#sky-directions)");
  t.addReal("lighting.sun_klux", &p.sunKlux, 1, 200, "klux",
            "assumption: extraterrestrial solar illuminance, about 128 klux");
  t.addReal("lighting.exposure_klux", &p.exposureKlux, 0.001, 1000, "klux",
            "assumption: noon sun + sky on flat ground is about 100-120 klux, mapped near 1.0");
  t.addBool("lighting.multiply_albedo", &p.multiplyAlbedo,
            "the article multiplies the lightmap by the colour map in software");
  t.addInt("lighting.sky_width", &p.skyWidth, 8, 8192, "texels", "sky dome image width (height = width / 2)");
  t.addReal("lighting.night.sky_r", &p.nightSkyR, 0, 1, "normalised", "assumption: dim bluish night sky");
  t.addReal("lighting.night.sky_g", &p.nightSkyG, 0, 1, "normalised", "assumption: dim bluish night sky");
  t.addReal("lighting.night.sky_b", &p.nightSkyB, 0, 1, "normalised", "assumption: dim bluish night sky");
  t.addBool("lighting.night.moon", &p.moon, "a full moon opposite the sun (assumption: no lunar orbit model)");
  t.addReal("lighting.night.moon_irradiance", &p.moonIrradiance, 0, 1, "normalised",
            "assumption: artistic; real moonlight (0.1-0.3 lux) is 1e-6 of noon");
  t.addBool("lighting.clouds.enabled", &p.clouds.enabled, "optional cloud shadows (Hoffman & Mitchell 2001)");
  t.addReal("lighting.clouds.coverage", &p.clouds.coverage, 0, 1, "fraction", user);
  t.addReal("lighting.clouds.opacity", &p.clouds.opacity, 0, 1, "fraction", user);
  t.addReal("lighting.clouds.scale_m", &p.clouds.scaleMetres, 10, 1e6, "m", "ground size of one texture tile");
  t.addReal("lighting.clouds.height_m", &p.clouds.heightMetres, 0, 20000, "m", "cloud base above the terrain");
  t.addReal("lighting.clouds.wind_east_m_per_h", &p.clouds.windEastMetresPerHour, -1e6, 1e6, "m/h", "time-lapse drift");
  t.addReal("lighting.clouds.wind_south_m_per_h", &p.clouds.windSouthMetresPerHour, -1e6, 1e6, "m/h",
            "time-lapse drift");
  t.addInt("lighting.clouds.seed", &p.clouds.seed, 0, std::numeric_limits<std::int32_t>::max(), "", user);
}

void validateParams(const DayCycleParams& p) {
  DayCycleParams copy = p;
  ParamTable table;
  describeParams(table, copy);
  for (const auto& param : table.params()) {
    double v = 0;
    if (const auto* i = std::get_if<std::int64_t*>(&param.field)) {
      v = static_cast<double>(**i);
    } else if (const auto* d = std::get_if<double*>(&param.field)) {
      v = **d;
    } else {
      continue;
    }
    if (!(v >= param.min && v <= param.max)) {
      std::ostringstream msg;
      msg << param.key << " = " << v << " is outside [" << param.min << ", " << param.max << "]"
          << (param.unit.empty() ? "" : " " + param.unit);
      throw LightingError(msg.str());
    }
  }
  if (p.skyDirections != 8 && p.skyDirections != 16 && p.skyDirections != 32) {
    throw LightingError("lighting.sky_directions = " + std::to_string(p.skyDirections) + " must be 8, 16 or 32");
  }
  if (p.endHour < p.startHour) {
    throw LightingError("lighting.end_hour = " + std::to_string(p.endHour) +
                        " is before lighting.start_hour = " + std::to_string(p.startHour));
  }
}

Precomputed precompute(Terrain terrain, int skyPatches, WorkerPool* pool, int skyDirections) {
  Precomputed pre;
  pre.terrain = std::move(terrain);
  pre.normals = terrainNormals(pre.terrain);
  pre.horizons = computeHorizons(pre.terrain, pool);
  pre.palette = buildNormalPalette(pre.normals);
  pre.sky = computeSkyFactors(pre.terrain, pre.horizons, pre.normals, skyPatches, skyDirections, pool);
  return pre;
}

double sunOcclusion(double horizon, double centre, double diameter, bool exactDisc) {
  const double half = diameter / 2;
  if (horizon <= centre - half) return 1.0;
  if (horizon >= centre + half) return 0.0;
  if (!exactDisc) return (centre + half - horizon) / diameter;  // (theta_max - phi) / alpha
  const double t = std::clamp((centre - horizon) / half, -1.0, 1.0);
  return 0.5 + (t * std::sqrt(1 - t * t) + std::asin(t)) / kPi;
}

void relight(const Precomputed& pre, const FrameLighting& light, const float* keyHorizonTan, const CloudLayer& clouds,
             const DayCycleParams& params, FloatImage& out, FloatImage* shadowMask, WorkerPool* pool) {
  const Terrain& t = pre.terrain;
  if (out.width != t.width || out.height != t.height || out.channels != 3) out = FloatImage(t.width, t.height, 3);
  if (shadowMask != nullptr && (shadowMask->width != t.width || shadowMask->height != t.height)) {
    *shadowMask = FloatImage(t.width, t.height, 1);
  }
  // The lighting table: the key light on each of the 256 palette normals.
  const Dir3 l = light.key.direction;
  std::array<std::array<float, 3>, kPaletteSize> table;
  for (int k = 0; k < kPaletteSize; ++k) {
    const Vec3& n = pre.palette.normals[k];
    const float d = std::max(0.0f, static_cast<float>(n.x * l.x + n.y * l.y + n.z * l.z));
    for (int c = 0; c < 3; ++c) table[k][c] = light.keyIrradiance[c] * d;
  }
  const double diameter = params.sunDiameterDeg * kDeg, e = light.key.elevation;
  const double lo = e - diameter / 2, hi = e + diameter / 2;
  const float tanLo = lo > -kPi / 2 ? static_cast<float>(std::tan(lo)) : -std::numeric_limits<float>::infinity();
  const float tanHi = hi < kPi / 2 ? static_cast<float>(std::tan(hi)) : std::numeric_limits<float>::infinity();
  const int patches = pre.sky.patches;
  const bool cloudy = params.clouds.enabled;
  const double hours = light.hour - params.startHour;

  // Local copies: the output stores below are floats too, so without them the compiler would have
  // to reload every coefficient after every store.
  float patchRadiance[kMaxSkyPatches * 3];
  for (int q = 0; q < patches; ++q)
    for (int c = 0; c < 3; ++c) patchRadiance[q * 3 + c] = light.patch[q][c];
  const bool albedo = params.multiplyAlbedo, exact = params.exactDisc;
  const std::uint8_t* __restrict paletteIndex = pre.palette.index.data();

  auto rows = [&](std::size_t block) {
    float cloudRow[kCloudChunk];
    const int y0 = static_cast<int>(block) * kRowBlock, y1 = std::min(t.height, y0 + kRowBlock);
    for (int y = y0; y < y1; ++y) {
      const std::size_t base = static_cast<std::size_t>(y) * t.width;
      for (int x0 = 0; x0 < t.width; x0 += kCloudChunk) {
        const int n = std::min(kCloudChunk, t.width - x0);
        if (cloudy) {
          clouds.transmittanceRow(y, x0, n, t.cellSize, hours, l, cloudRow);
        }
        float* __restrict o = out.pixels.data() + (base + x0) * 3;
        const float* __restrict sky = pre.sky.factor.data() + (base + x0) * patches * 3;
        const float* __restrict horizon = keyHorizonTan + base + x0;
        float* __restrict mask = shadowMask != nullptr ? shadowMask->pixels.data() + base + x0 : nullptr;
        for (int x = 0; x < n; ++x, o += 3, sky += static_cast<std::ptrdiff_t>(patches) * 3) {
          const std::size_t i = base + x0 + x;
          const float h = horizon[x];
          float vis = h <= tanLo   ? 1.0f
                      : h >= tanHi ? 0.0f
                                   : static_cast<float>(sunOcclusion(std::atan(h), e, diameter, exact));
          if (cloudy) vis *= cloudRow[x];
          const float* lit = table[paletteIndex[i]].data();
          float v[3] = {vis * lit[0], vis * lit[1], vis * lit[2]};
          for (int q = 0; q < patches; ++q) {
            for (int c = 0; c < 3; ++c) v[c] += patchRadiance[q * 3 + c] * sky[q * 3 + c];
          }
          if (albedo) {
            for (int c = 0; c < 3; ++c) v[c] *= t.albedoAt(i, c);
          }
          o[0] = v[0];
          o[1] = v[1];
          o[2] = v[2];
          if (mask != nullptr) mask[x] = vis;
        }
      }
    }
  };
  const std::size_t blocks = static_cast<std::size_t>((t.height + kRowBlock - 1) / kRowBlock);
  if (pool != nullptr) {
    pool->parallelFor(blocks, rows);
  } else {
    for (std::size_t b = 0; b < blocks; ++b) rows(b);
  }
}

void cosineLayer(const Precomputed& pre, const Dir3& l, FloatImage& out) {
  const Terrain& t = pre.terrain;
  if (out.width != t.width || out.height != t.height || out.channels != 1) out = FloatImage(t.width, t.height, 1);
  for (std::size_t i = 0; i < pre.normals.size(); ++i) {
    const Vec3& n = pre.normals[i];
    out.pixels[i] = static_cast<float>(std::max(0.0, n.x * l.x + n.y * l.y + n.z * l.z));
  }
}

void renderSky(const FrameLighting& light, const DayCycleParams& params, FloatImage& sky) {
  const int w = static_cast<int>(params.skyWidth), h = std::max(1, w / 2);
  if (sky.width != w || sky.height != h || sky.channels != 3) sky = FloatImage(w, h, 3);
  const double scale = kPi / params.exposureKlux;  // kcd/m^2 -> pi L / exposure
  const Dir3 evalSun = directionAt(std::max(light.sun.elevation, kDayFullDeg * kDeg), light.sun.azimuth);
  const PreethamSky model(params.turbidity, evalSun);
  const double night[3] = {params.nightSkyR, params.nightSkyG, params.nightSkyB};
  const double half = params.sunDiameterDeg * kDeg / 2, cosHalf = std::cos(half);
  const double discScale = kPi / (2 * kPi * (1 - cosHalf));  // irradiance -> pi L over the drawn disc
  const Dir3 k = light.key.direction;
  for (int v = 0; v < h; ++v) {
    const double elevation = (1.0 - (v + 0.5) / h) * kPi / 2;
    for (int u = 0; u < w; ++u) {
      const double azimuth = (u + 0.5) / w * 2 * kPi - kPi / 2;  // compass (north = 0) -> grid basis
      const Dir3 d = directionAt(elevation, azimuth);
      Rgb L{0, 0, 0};
      if (light.dayWeight > 0) L = model.radiance(d);
      float* o = sky.at(u, v);
      const bool inDisc = d.x * k.x + d.y * k.y + d.z * k.z >= cosHalf;
      for (int c = 0; c < 3; ++c) {
        double value = light.dayWeight * L[c] * scale + night[c];
        if (inDisc) value += light.keyIrradiance[c] * discScale;
        o[c] = static_cast<float>(value);
      }
    }
  }
}

void toRgba8(const FloatImage& img, Rgba8Image& out) {
  if (out.width != img.width || out.height != img.height) out = Rgba8Image(img.width, img.height);
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = img.pixels[i * img.channels + (img.channels >= 3 ? c : 0)];
      const float s = std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f;
      out.pixels[i * 4 + c] = static_cast<std::uint8_t>(s);
    }
    out.pixels[i * 4 + 3] = 0x80;
  }
}

DayCycleGenerator::DayCycleGenerator(Terrain terrain, const DayCycleParams& params, WorkerPool* pool,
                                     FloatImage cloudTexture)
    : params_(params), pool_(pool), clouds_((validateParams(params), params.clouds), std::move(cloudTexture)) {
  pre_ = precompute(std::move(terrain), static_cast<int>(params_.skyPatches), pool_,
                    static_cast<int>(params_.skyDirections));
  keyHorizon_.resize(pre_.terrain.texels());
}

double frameHour(const DayCycleParams& p, int frame) {
  const double span = p.endHour - p.startHour;
  if (p.frames <= 1) return p.startHour;
  // A whole day loops: the last frame stops one step short of the first again.
  const double steps = span >= 24.0 ? static_cast<double>(p.frames) : static_cast<double>(p.frames - 1);
  return p.startHour + span * frame / steps;
}

double DayCycleGenerator::frameHour(int frame) const {
  return lighting::frameHour(params_, frame);
}

FrameLighting DayCycleGenerator::frameLighting(int frame) const {
  const DayCycleParams& p = params_;
  FrameLighting f;
  f.hour = frameHour(frame);
  if (p.fixedSun) {
    // Compass azimuth -> grid basis (from east towards south): north is -90 degrees.
    f.sun = positionOf(directionAt(p.sunElevationDeg * kDeg, (p.sunAzimuthDeg - 90.0) * kDeg));
  } else {
    f.sun = sunPosition(p.latitudeDeg, static_cast<int>(p.dayOfYear), std::fmod(f.hour, 24.0));
  }
  f.dayWeight = smoothstep(kNightDeg * kDeg, kDayFullDeg * kDeg, f.sun.elevation);

  // Sky patches: Preetham radiance, cosine-weighted over each patch's sectors.
  const Dir3 evalSun = directionAt(std::max(f.sun.elevation, kDayFullDeg * kDeg), f.sun.azimuth);
  const PreethamSky model(p.turbidity, evalSun);
  const int patches = static_cast<int>(p.skyPatches);
  // The patches cover the same sectors as the sky factors' (patchOfSector); 32 azimuth samples in all.
  const int sectors = static_cast<int>(p.skyDirections), kAz = 32 / sectors;
  constexpr int kTheta = 12;
  std::array<Rgb, kMaxSkyPatches> sum{};
  std::array<double, kMaxSkyPatches> weight{};
  if (f.dayWeight > 0) {
    for (int s = 0; s < sectors; ++s) {
      const int patch = patchOfSector(s, patches, sectors);
      for (int a = 0; a < kAz; ++a) {
        const double az = (s - 0.5 + (a + 0.5) / kAz) * 2 * kPi / sectors;
        for (int j = 0; j < kTheta; ++j) {
          const double theta = (j + 0.5) / kTheta * kPi / 2;
          const double w = std::cos(theta) * std::sin(theta);
          const Rgb L = model.radiance(directionAt(kPi / 2 - theta, az));
          for (int c = 0; c < 3; ++c) sum[patch][c] += w * L[c];
          weight[patch] += w;
        }
      }
    }
  }
  const double night[3] = {p.nightSkyR, p.nightSkyG, p.nightSkyB};
  for (int q = 0; q < patches; ++q) {
    for (int c = 0; c < 3; ++c) {
      const double day = weight[q] > 0 ? sum[q][c] / weight[q] * kPi / p.exposureKlux : 0.0;
      f.patch[q][c] = static_cast<float>(f.dayWeight * day + night[c]);
    }
  }

  // The key light: the sun while any of its disc can be above the horizontal, else the moon.
  const double half = p.sunDiameterDeg * kDeg / 2;
  if (f.sun.elevation + half > 0 || !p.moon) {
    f.key = f.sun;
    const Rgb t = sunTransmittance(p.turbidity, kPi / 2 - f.sun.elevation);
    for (int c = 0; c < 3; ++c) f.keyIrradiance[c] = static_cast<float>(p.sunKlux * t[c] / p.exposureKlux);
  } else {
    f.keyIsMoon = true;
    f.key = positionOf({-f.sun.direction.x, -f.sun.direction.y, -f.sun.direction.z});
    const double rise = smoothstep(0.0, 5.0 * kDeg, f.key.elevation);
    for (int c = 0; c < 3; ++c) f.keyIrradiance[c] = static_cast<float>(p.moonIrradiance * kMoonColour[c] * rise);
  }
  return f;
}

void DayCycleGenerator::renderFrame(int frame, FloatImage& lightmap, FloatImage& sky, FloatImage* shadowMask) {
  if (frame < 0 || frame >= frameCount()) {
    throw LightingError("frame " + std::to_string(frame) + " is outside 0.." + std::to_string(frameCount() - 1));
  }
  const FrameLighting f = frameLighting(frame);
  if (params_.shadowRays) {
    sweepRays(pre_.terrain, f.key.azimuth, keyHorizon_.data(), pool_);
  } else {
    sweepAzimuth(pre_.terrain, f.key.azimuth, keyHorizon_.data(), pool_);
  }
  relight(pre_, f, keyHorizon_.data(), clouds_, params_, lightmap, shadowMask, pool_);
  renderSky(f, params_, sky);
}

void DayCycleGenerator::renderFrame(int frame, Rgba8Image& lightmap, Rgba8Image& sky) {
  renderFrame(frame, scratchLight_, scratchSky_);
  toRgba8(scratchLight_, lightmap);
  toRgba8(scratchSky_, sky);
}

}  // namespace vbim::lighting
