#include "lighting/sky_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vbim::lighting {

double airMass(double zenith) {
  const double zDeg = std::min(zenith * 180.0 / std::numbers::pi, 90.0);
  return 1.0 / (std::cos(zDeg * std::numbers::pi / 180.0) + 0.15 * std::pow(93.885 - zDeg, -1.253));
}

Rgb sunTransmittance(double turbidity, double zenith) {
  constexpr double kLambda[3] = {0.68, 0.55, 0.44};  // micrometres
  const double m = airMass(zenith);
  const double beta = 0.04608 * turbidity - 0.04586;  // Angstrom turbidity coefficient
  Rgb t{};
  for (int c = 0; c < 3; ++c) {
    const double rayleigh = 0.008735 * std::pow(kLambda[c], -4.08);
    const double aerosol = beta * std::pow(kLambda[c], -1.3);
    t[c] = std::exp(-(rayleigh + aerosol) * m);
  }
  return t;
}

double PreethamSky::Perez::f(double cosTheta, double gamma) const {
  const double cg = std::cos(gamma);
  return (1 + a * std::exp(b / cosTheta)) * (1 + c * std::exp(d * gamma) + e * cg * cg);
}

PreethamSky::PreethamSky(double T, const Dir3& sun) : sun_(sun) {
  lumY_ = {0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771, -0.0670 * T + 0.3703};
  chromX_ = {-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989,
             -0.0033 * T + 0.0452};
  chromY_ = {-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537,
             -0.0109 * T + 0.0529};
  const double thetaS = std::acos(std::clamp(sun.z, 0.0, 1.0));
  const double chi = (4.0 / 9.0 - T / 120.0) * (std::numbers::pi - 2 * thetaS);
  zenithY_ = (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
  const double t2 = T * T, s1 = thetaS, s2 = s1 * s1, s3 = s2 * s1;
  zenithX_ = t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s1) +
             T * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s1 + 0.00394) +
             (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s1 + 0.25886);
  zenithYc_ = t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s1) +
              T * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s1 + 0.00516) +
              (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s1 + 0.26688);
  normY_ = lumY_.f(1.0, thetaS);
  normX_ = chromX_.f(1.0, thetaS);
  normYc_ = chromY_.f(1.0, thetaS);
}

Rgb PreethamSky::radiance(const Dir3& v) const {
  // The Perez fit diverges at the horizon (1/cos theta); hold the view a little above it.
  const double cosTheta = std::max(v.z, 0.02);
  const double cosGamma = std::clamp(v.x * sun_.x + v.y * sun_.y + v.z * sun_.z, -1.0, 1.0);
  const double gamma = std::acos(cosGamma);
  const double Y = zenithY_ * lumY_.f(cosTheta, gamma) / normY_;
  const double x = zenithX_ * chromX_.f(cosTheta, gamma) / normX_;
  const double y = zenithYc_ * chromY_.f(cosTheta, gamma) / normYc_;
  Rgb rgb = xyYToLinearSrgb(x, y, std::max(Y, 0.0));
  for (double& c : rgb) c = std::max(c, 0.0);
  return rgb;
}

Rgb xyYToLinearSrgb(double x, double y, double Y) {
  if (y <= 1e-9) return {0, 0, 0};
  const double X = x / y * Y, Z = (1 - x - y) / y * Y;
  return {3.2406 * X - 1.5372 * Y - 0.4986 * Z, -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
          0.0557 * X - 0.2040 * Y + 1.0570 * Z};
}

}  // namespace vbim::lighting
