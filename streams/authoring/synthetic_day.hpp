// A small deterministic day-cycle generator for sample streams and tests, until Technique A
// (lighting/) produces real content: a smooth height field lit by a sun that crosses the sky, with
// soft shadows from a horizon march, sky ambient, and a matching sky dome. Weather "clear" has a
// strong sun and crisp shadows; "overcast" a dim diffuse sun, soft shadows and a grey sky.
// Output is linear light (tone-map it like an HDR render). Same parameters, same floats.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {

struct SyntheticDay {
  int width = 256, height = 256;       // lightmap
  int skyWidth = 128, skyHeight = 64;  // sky dome (equirectangular upper hemisphere)
  std::uint32_t frames = 48;           // one full day
  std::string weather = "clear";       // "clear" or "overcast"
};

// Throws AuthoringError for an unknown weather or a size below 16.
void checkSyntheticDay(const SyntheticDay& day);
FloatRgbImage syntheticLightmap(const SyntheticDay& day, std::uint32_t frame);
FloatRgbImage syntheticSky(const SyntheticDay& day, std::uint32_t frame);

}  // namespace vbim::streams
