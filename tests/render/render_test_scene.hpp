// A small scene for the renderer tests: the procedural terrain at 64x64 texels of 20 m, a 24-frame
// day, and streamed-like frames (sRGB-coded 8-bit lightmap and sky) straight from the generator.
#pragma once

#include "lighting/day_cycle.hpp"
#include "render/renderer.hpp"
#include "runtime/image.hpp"

namespace vbim::render::test {

lighting::Terrain smallTerrain();
lighting::DayCycleParams smallDay();
RenderSettings smallSettings();

struct StreamedFrame {
  Rgba8Image lightmap, sky;
  lighting::FloatImage shadowMask;  // the generator's own O * c per texel
};
// Frame `frame` of smallDay() on smallTerrain(), tone-mapped as the authoring does (clamp, sRGB).
StreamedFrame streamedFrame(int frame);

// 64-bit FNV-1a of the RGBA bytes.
std::uint64_t hashImage(const Rgba8Image& img);

}  // namespace vbim::render::test
