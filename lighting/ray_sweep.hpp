// The horizon along an arbitrary azimuth, per texel along the texel's own ray (issue #20: shadows
// right at every sun azimuth).
//
// azimuth_sweep.hpp shares one sheared grid line between all the texels on it; a line wanders up to
// half a cell to either side of a texel's true ray, so at oblique azimuths the occluder it finds for
// a texel can sit beside the texel's ray, not on it (false self-shadow from a sideways neighbour).
// Here the sweep lines are straight: line j is the set of points (u, j + u * tan) for every integer
// step u along the major axis (the axis closer to the azimuth), its height at each step linearly
// interpolated between the two texels across the minor axis. A texel lies between two neighbouring
// lines, at fraction f from the lower one; its own ray runs parallel to them at the same fraction.
// Each line's O(n) hull scan keeps the upper hull of its samples ahead; the texel asks both lines'
// hulls, with its own height at its own position, for the steepest point ahead (a binary search),
// and its horizon tangent is (1 - f) * lower + f * upper: the horizons of the two parallel rays that
// bracket the texel's own ray (each less than a cell away, never a sideways neighbour's line),
// interpolated to it. Measured against an exact per-texel ray in tests/lighting/shadow_ray_test.cpp
// (docs/lighting.md#shadows-at-any-azimuth).
//
// Fixed point: the line's minor coordinate in 1/65536 cell (the tangent rounded to 2^-16: the ray
// drifts by at most 2^-17 cell per step) and heights in 1/65536 height unit, so the hull compares
// exact integers and the scan equals the brute force over the same samples bit for bit.
#pragma once

#include "lighting/terrain.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::lighting {

// Writes, per texel, the tangent of the horizon elevation looking towards `azimuth` (radians, from
// +col towards +row), clamped at 0. `out` has width * height entries. Independent of the pool.
void sweepRays(const Terrain& terrain, double azimuth, float* out, WorkerPool* pool = nullptr);

// O(n^1.5) reference over the same line samples and blend. Tests only.
void sweepRaysBruteForce(const Terrain& terrain, double azimuth, float* out);

}  // namespace vbim::lighting
