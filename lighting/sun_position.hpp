// Where the sun is: the simple declination / hour-angle formulas of docs/lighting.md#sun-position
// (declination 23.44 deg * sin(2 pi (284 + n) / 365), hour angle 15 deg per hour from solar noon).
// Good to a few tenths of a degree, which is below the sun's own diameter; hours are local solar
// time (no equation of time, no longitude).
#pragma once

namespace vbim::lighting {

struct Dir3 {
  double x = 0, y = 0, z = 0;  // (col = east, row = south, up)
};

struct SunPosition {
  double elevation = 0;  // radians above the horizontal (negative below)
  double azimuth = 0;    // radians in the grid basis: from east (+col) towards south (+row)
  Dir3 direction;        // unit vector towards the sun
};

double solarDeclination(int dayOfYear);  // radians
SunPosition sunPosition(double latitudeDeg, int dayOfYear, double solarHour);

// Compass azimuth (0 = north, clockwise, degrees) of a grid azimuth, for reports.
double compassDegrees(double gridAzimuth);

}  // namespace vbim::lighting
