// What lights the objects in one frame, worked out on the CPU from the streamed images, so the
// objects follow what the player shows (a stale lightmap during a stall included):
//
// - The sun (or moon) direction and colour for the frame's time of day, from the Technique A
//   generator's settings (lighting/day_cycle.hpp); the run directory does not record them, so they
//   come from --lighting-config (defaults: those of the committed samples).
// - The stream's scale: the streamed lightmap is the generator's irradiance times an unknown
//   exposure, sRGB-coded. The generator's unshadowed prediction for the frame, divided into the
//   decoded lightmap texel by texel, gives that scale where the texel is lit (upper quartile of the
//   ratios: shadows only lower them).
// - The sun's visibility per texel (the Hargreaves shadow term taken from the lightmap): what the
//   lightmap holds beyond the sky-only prediction, as a fraction of the direct term it would hold
//   in full sun: O = clamp((lm / a - sky) / sun, 0, 1). Texels whose own slope turns away from the
//   sun have no direct term to measure and count as shadowed.
// - The sky colour for the hemisphere (Hargreaves' sky, IceFall's "SkyColor"): the streamed sky
//   dome's cosine-weighted mean, i.e. the sky's irradiance on a level surface in stream units.
//
// Everything is in stream units: linear values of the decoded 8-bit codes (1.0 = code 255).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "lighting/day_cycle.hpp"
#include "runtime/image.hpp"

namespace vbim::render {

struct FrameLight {
  double hour = 0;
  std::array<float, 3> sunDirection{0, 1, 0};  // world (x east, y up, z south), towards the light
  std::array<float, 3> sunIrradiance{};        // on a surface facing the light, stream units
  std::array<float, 3> skyIrradiance{};        // on a level surface, stream units
  float streamScale = 1;                       // a: decoded lightmap / generator irradiance
  int width = 0, height = 0;
  std::vector<float> sunVisibility;  // O per lightmap texel, 0..1, row-major
};

// sRGB code -> linear (IEC 61966-2-1), the inverse of the authoring tone mapping's transfer.
float srgbToLinear(std::uint8_t code);

class SceneLighting {
 public:
  // Precomputes horizons and sky factors for `terrain` (about 0.1 s for 256x256). Throws
  // RenderError if the settings are out of range.
  SceneLighting(lighting::Terrain terrain, const lighting::DayCycleParams& params, int loopFrame = 0);

  // The stream frame a sequence number shows (after the last frame, playback wraps to loopFrame).
  int frameOfSeq(std::int64_t seq) const;

  // `lightmap` must have the terrain's size; `sky` may be null (then the sky colour comes from the
  // generator's sky patches).
  FrameLight evaluate(std::int64_t seq, const Rgba8Image& lightmap, const Rgba8Image* sky);

  const lighting::Terrain& terrain() const { return generator_->precomputed().terrain; }
  const lighting::DayCycleParams& params() const { return generator_->params(); }

 private:
  std::unique_ptr<lighting::DayCycleGenerator> generator_;
  int loopFrame_;
  std::vector<float> openHorizon_;
  lighting::FloatImage lit_, skyOnly_;
};

}  // namespace vbim::render
