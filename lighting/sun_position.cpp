#include "lighting/sun_position.hpp"

#include <cmath>
#include <numbers>

namespace vbim::lighting {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

double solarDeclination(int dayOfYear) {
  return 23.44 * kDeg * std::sin(2 * std::numbers::pi * (284 + dayOfYear) / 365.0);
}

SunPosition sunPosition(double latitudeDeg, int dayOfYear, double solarHour) {
  const double lat = latitudeDeg * kDeg, dec = solarDeclination(dayOfYear);
  const double hourAngle = 15.0 * kDeg * (solarHour - 12.0);
  // East, north, up components of the unit vector towards the sun.
  const double east = -std::cos(dec) * std::sin(hourAngle);
  const double north = std::sin(dec) * std::cos(lat) - std::cos(dec) * std::cos(hourAngle) * std::sin(lat);
  const double up = std::sin(dec) * std::sin(lat) + std::cos(dec) * std::cos(hourAngle) * std::cos(lat);
  SunPosition s;
  s.direction = {east, -north, up};  // rows grow southwards
  s.elevation = std::asin(std::fmax(-1.0, std::fmin(1.0, up)));
  s.azimuth = std::atan2(-north, east);
  return s;
}

double compassDegrees(double gridAzimuth) {
  double c = 90.0 + gridAzimuth / kDeg;
  c = std::fmod(c, 360.0);
  return c < 0 ? c + 360.0 : c;
}

}  // namespace vbim::lighting
