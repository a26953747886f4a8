// Sun and sky colour over the day: Preetham, Shirley & Smits 1999, "A Practical Analytic Model for
// Daylight" (coefficients from the paper and its appendix; docs/lighting.md#sky-model). Radiances are
// linear sRGB with Y in kcd/m^2, so pi * radiance is an illuminance in klux; the generator divides by
// its exposure to normalise.
#pragma once

#include <array>

#include "lighting/sun_position.hpp"

namespace vbim::lighting {

using Rgb = std::array<double, 3>;

// Kasten 1966 relative optical air mass at zenith angle `zenith` (radians, clamped to 90 deg).
double airMass(double zenith);

// Spectral transmittance of the direct sun (Rayleigh + Angstrom aerosol, Preetham's appendix),
// sampled at 680 / 550 / 440 nm for R / G / B. Ozone, mixed gases and water vapour are left out:
// they mostly dim and barely tint in the visible.
Rgb sunTransmittance(double turbidity, double zenith);

class PreethamSky {
 public:
  // turbidity: 2-6 is the model's fitted range; sun: unit vector towards the sun, z up. The model
  // is invalid below the horizon: callers evaluate it at a small positive elevation and fade.
  PreethamSky(double turbidity, const Dir3& sun);
  // Radiance towards unit direction `view` (z >= 0 is sky), linear sRGB, kcd/m^2 (never negative).
  Rgb radiance(const Dir3& view) const;

 private:
  struct Perez {
    double a, b, c, d, e;
    double f(double cosTheta, double gamma) const;
  };
  Perez lumY_, chromX_, chromY_;
  double zenithY_ = 0, zenithX_ = 0, zenithYc_ = 0;
  double normY_ = 1, normX_ = 1, normYc_ = 1;  // F(0, theta_s) per channel
  Dir3 sun_;
};

Rgb xyYToLinearSrgb(double x, double y, double Y);

}  // namespace vbim::lighting
