// Technique A as a content generator: a day (or day/night) cycle of normalised irradiance
// lightmaps and matching sky dome images, one frame at a time, so an encoder can consume frames
// without files.
//
//   lightmap(p, t) = O(p, t) c(p, t) E_key(t) max(0, N_q(p) . L(t)) + sum_p E_patch,p(t) S_p(p)
//                    [ x albedo(p) when multiplyAlbedo ]
//
// O: soft occlusion of the sun (or moon) disc by the horizon along its azimuth; c: cloud shadow;
// N_q: the texel's palette normal (256-entry lighting table per frame); S_p: the static
// Stewart-Langer sky factors; E_patch,p = pi L_p / exposure with L_p the Preetham sky radiance
// averaged (cosine-weighted) over patch p, faded into a dim night sky below the horizon.
// Values are irradiance / exposure: 1.0 = `exposureKlux` klux.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "lighting/clouds.hpp"
#include "lighting/float_image.hpp"
#include "lighting/horizon_scan.hpp"
#include "lighting/normal_palette.hpp"
#include "lighting/sky_factor.hpp"
#include "lighting/sun_position.hpp"
#include "lighting/terrain.hpp"
#include "runtime/image.hpp"

namespace vbim {
class ParamTable;
class WorkerPool;
}  // namespace vbim

namespace vbim::lighting {

struct DayCycleParams {
  double latitudeDeg = 45.0;
  std::int64_t dayOfYear = 172;  // 21 June
  double startHour = 6.0;        // local solar time: daylight at the default place and day (sunrise ~4:20)
  double endHour = 22.0;
  std::int64_t frames = 120;
  // The sun given directly instead of by place and time: compass azimuth (0 = north, 90 = east,
  // clockwise seen from above) and elevation above the horizontal, the same in every frame.
  bool fixedSun = false;
  double sunAzimuthDeg = 180.0;
  double sunElevationDeg = 45.0;
  double sunDiameterDeg = 1.5;  // wider than the real 0.53 deg: softer edges, anti-aliasing (docs/lighting.md#sun-disc)
  bool exactDisc = false;       // circular-segment occlusion instead of the article's linear ramp
  // Sun shadows along each texel's own ray (lighting/ray_sweep.hpp); false: along the texel's
  // sheared grid line (lighting/azimuth_sweep.hpp), which over-shadows at oblique azimuths
  // (docs/lighting.md#shadows-at-any-azimuth).
  bool shadowRays = true;
  double turbidity = 3.0;
  std::int64_t skyPatches = 2;
  std::int64_t skyDirections = 8;  // sky-factor sectors: 8 (the article's), 16 or 32
  double sunKlux = 128.0;          // direct normal illuminance above the atmosphere
  double exposureKlux = 120.0;     // irradiance that maps to 1.0
  bool multiplyAlbedo = false;
  std::int64_t skyWidth = 256;  // sky dome image: skyWidth x skyWidth / 2
  // Night: a dim bluish sky and, optionally, a full moon opposite the sun (normalised units).
  double nightSkyR = 0.004, nightSkyG = 0.006, nightSkyB = 0.014;
  bool moon = true;
  double moonIrradiance = 0.05;
  CloudParams clouds;
};

// Registers every field under "lighting." with unit, range and source.
void describeParams(ParamTable& table, DayCycleParams& p);
// Fails (LightingError naming the key and the allowed range) on any out-of-range value.
void validateParams(const DayCycleParams& p);
// Local solar hour of frame `frame` (DayCycleGenerator::frameHour, without a generator).
double frameHour(const DayCycleParams& p, int frame);

// What lights one frame, in normalised units.
struct FrameLighting {
  double hour = 0;
  SunPosition sun;
  bool keyIsMoon = false;
  SunPosition key;                                           // the light that casts shadows this frame (sun or moon)
  std::array<float, 3> keyIrradiance{};                      // on a surface facing the key light, before occlusion
  std::array<std::array<float, 3>, kMaxSkyPatches> patch{};  // pi L_p / exposure
  double dayWeight = 1;                                      // 1 in daylight, 0 at night
};

// The light-independent part: horizons, normals, palette, sky factors.
struct Precomputed {
  Terrain terrain;
  std::vector<Vec3> normals;
  HorizonMaps horizons;
  NormalPalette palette;
  SkyFactors sky;
};

Precomputed precompute(Terrain terrain, int skyPatches, WorkerPool* pool = nullptr, int skyDirections = 8);

// Sun visibility for horizon elevation `horizon`, disc centre elevation `centre`, angular
// diameter `diameter` (radians): 1 below centre - d/2, 0 above centre + d/2; linear in between
// (Hoffman & Mitchell) or the exact visible area of the disc.
double sunOcclusion(double horizon, double centre, double diameter, bool exactDisc);

// One frame's relight, given the key light's horizon tangents per texel (lighting/azimuth_sweep.hpp).
// `lightmap` is resized to RGB; `shadowMask` (optional) receives O * c per texel.
void relight(const Precomputed& pre, const FrameLighting& light, const float* keyHorizonTan, const CloudLayer& clouds,
             const DayCycleParams& params, FloatImage& lightmap, FloatImage* shadowMask = nullptr,
             WorkerPool* pool = nullptr);

// Debug layer: max(0, N . L) per texel with the exact normals (not the palette's), single channel,
// comparable with a GIS hillshade of the same light direction.
void cosineLayer(const Precomputed& pre, const Dir3& light, FloatImage& out);

// The sky dome: latitude-longitude over the upper hemisphere, width x width / 2; column 0 = north,
// azimuth grows clockwise (east at a quarter of the width); row 0 = zenith, the last row = horizon.
// Values are pi L / exposure, the sun and moon discs included.
void renderSky(const FrameLighting& light, const DayCycleParams& params, FloatImage& sky);

// Linear, clamped to [0, 1], 1.0 -> 255; alpha 0x80 (= 1.0 on the GS).
void toRgba8(const FloatImage& image, Rgba8Image& out);

class DayCycleGenerator {
 public:
  // Validates the parameters, then precomputes (horizons, palette, sky factors). `pool` may be null.
  DayCycleGenerator(Terrain terrain, const DayCycleParams& params, WorkerPool* pool = nullptr,
                    FloatImage cloudTexture = {});

  int frameCount() const { return static_cast<int>(params_.frames); }
  double frameHour(int frame) const;
  FrameLighting frameLighting(int frame) const;

  // Frames may be rendered in any order; the result depends only on the frame index.
  void renderFrame(int frame, FloatImage& lightmap, FloatImage& sky, FloatImage* shadowMask = nullptr);
  void renderFrame(int frame, Rgba8Image& lightmap, Rgba8Image& sky);

  const Precomputed& precomputed() const { return pre_; }
  const DayCycleParams& params() const { return params_; }

 private:
  DayCycleParams params_;
  WorkerPool* pool_;
  Precomputed pre_;
  CloudLayer clouds_;
  std::vector<float> keyHorizon_;
  FloatImage scratchLight_, scratchSky_;
};

}  // namespace vbim::lighting
