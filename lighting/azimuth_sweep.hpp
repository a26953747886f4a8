// The horizon along an arbitrary azimuth, for the sun (and moon) of one frame.
//
// The sun's azimuth changes through the day at any real latitude, so one horizon angle "along the
// arc" is exact only for a sun moving in a vertical plane. Frames are made offline, so each frame
// runs one O(n) hull scan along the sun's actual azimuth instead (docs/lighting.md#sun-path).
//
// Lines are sheared grid lines: along the major axis (the one closer to the azimuth) each line takes
// one texel per step, and its minor coordinate is round(u * tan). Every texel lies on exactly one
// line. Positions along the azimuth are the texels' projections onto it in fixed point (1/4096 cell),
// so the scan is exact for these samples and equals the brute-force maximum bit for bit.
#pragma once

#include <cstdint>

#include "lighting/terrain.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::lighting {

// Writes, per texel, the tangent of the horizon elevation looking towards `azimuth` (radians, from
// +col towards +row), clamped at 0. `out` has width * height entries.
void sweepAzimuth(const Terrain& terrain, double azimuth, float* out, WorkerPool* pool = nullptr);

// O(n^2) reference over the same line samples. Tests only.
void sweepAzimuthBruteForce(const Terrain& terrain, double azimuth, float* out);

}  // namespace vbim::lighting
