// Horizon angles as 16-bit fixed point, the way Hoffman & Mitchell store them: 0x0000 = 0 degrees
// (horizontal) and 0xFFFF = 90 degrees (zenith) ("scaled so that a quarter-circle fills the [0, 1]
// range, and stored as 16-bit fixed-point numbers", Hoffman & Mitchell GDC 2001).
#pragma once

#include <cstdint>
#include <numbers>

namespace vbim::lighting {

inline constexpr double kAngleUnit = (std::numbers::pi / 2) / 65535.0;  // radians per code

inline double angleFromCode(std::uint16_t code) {
  return code * kAngleUnit;
}
std::uint16_t codeFromAngle(double radians);  // clamps to [0, pi/2], rounds to nearest

// Code of atan(t) for t >= 0 (negative t gives 0: the zero-elevation clamp). A 4097-entry table of
// atan on [0, 1] with linear interpolation (error < 1e-8 rad, far below one code of 2.4e-5 rad),
// and atan(t) = pi/2 - atan(1/t) above 1: a few nanoseconds instead of a libm call, because the
// scans convert one slope per texel and direction.
std::uint16_t codeFromTangent(double t);

}  // namespace vbim::lighting
