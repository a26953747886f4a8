// Item 3: sun position, sun colour, Preetham sky, soft-shadow occlusion (and item 5's theta_min /
// theta_max rule).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lighting/day_cycle.hpp"
#include "lighting/sky_model.hpp"
#include "lighting/sun_position.hpp"

namespace vbim::lighting {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(SunOcclusion, OneBelowThetaMinZeroAboveThetaMax) {
  const double centre = 20 * kDeg, alpha = 2 * kDeg;
  for (bool exact : {false, true}) {
    EXPECT_EQ(sunOcclusion(0.0, centre, alpha, exact), 1.0);
    EXPECT_EQ(sunOcclusion(centre - alpha / 2, centre, alpha, exact), 1.0);
    EXPECT_EQ(sunOcclusion(centre - alpha / 2 - 1e-9, centre, alpha, exact), 1.0);
    EXPECT_EQ(sunOcclusion(centre + alpha / 2, centre, alpha, exact), 0.0);
    EXPECT_EQ(sunOcclusion(centre + alpha / 2 + 1e-9, centre, alpha, exact), 0.0);
    EXPECT_EQ(sunOcclusion(80 * kDeg, centre, alpha, exact), 0.0);
    EXPECT_NEAR(sunOcclusion(centre, centre, alpha, exact), 0.5, 1e-12);
    double last = 1.0;
    for (int i = 0; i <= 100; ++i) {  // monotone in between
      const double v = sunOcclusion(centre - alpha / 2 + alpha * i / 100, centre, alpha, exact);
      EXPECT_LE(v, last + 1e-12);
      last = v;
    }
  }
  // The article's ramp: (theta_max - phi) / alpha.
  EXPECT_NEAR(sunOcclusion(centre + alpha / 4, centre, alpha, false), 0.25, 1e-12);
  // The two forms differ by at most 0.058 (docs/lighting.md#sun-disc).
  double gap = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double h = centre - alpha / 2 + alpha * i / 1000;
    gap = std::max(gap, std::fabs(sunOcclusion(h, centre, alpha, false) - sunOcclusion(h, centre, alpha, true)));
  }
  EXPECT_NEAR(gap, 0.058, 0.003);
}

TEST(SunPosition, MatchesSolposAtMidsummerNoon) {
  // GRASS r.sunmask (SOLPOS; docs/lighting.md#sun-position): 2024-06-21 (day 173) at 45.165 N, solar
  // noon: elevation 68.27 deg, due south.
  const SunPosition s = sunPosition(45.165, 173, 12.0);
  EXPECT_NEAR(s.elevation / kDeg, 68.27, 0.1);
  EXPECT_NEAR(compassDegrees(s.azimuth), 180.0, 1e-6);
  EXPECT_NEAR(s.direction.x, 0.0, 1e-12);
  EXPECT_GT(s.direction.y, 0.0);  // south is +row
}

TEST(SunPosition, RisesInTheEastAndSetsInTheWest) {
  const SunPosition rise = sunPosition(0.0, 80, 6.0), set = sunPosition(0.0, 80, 18.0);  // equinox, equator
  EXPECT_NEAR(rise.elevation / kDeg, 0.0, 0.5);
  EXPECT_NEAR(compassDegrees(rise.azimuth), 90.0, 0.5);
  EXPECT_NEAR(compassDegrees(set.azimuth), 270.0, 0.5);
  EXPECT_GT(rise.direction.x, 0.99);                                                    // east is +col
  EXPECT_NEAR(sunPosition(-33.9, 172, 12.0).elevation / kDeg, 90 - 33.9 - 23.44, 0.1);  // southern winter
  EXPECT_NEAR(compassDegrees(sunPosition(-33.9, 172, 12.0).azimuth), 0.0, 1e-6);        // sun to the north
}

TEST(SunColour, TransmittanceMatchesTheNotesTable) {
  const double zen[] = {0.0, 45.0, 80.0};
  const Rgb expected[] = {{0.823, 0.740, 0.596}, {0.760, 0.654, 0.481}, {0.337, 0.186, 0.056}};
  for (int i = 0; i < 3; ++i) {
    const Rgb t = sunTransmittance(3.0, zen[i] * kDeg);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], expected[i][c], 0.004) << zen[i] << " " << c;
  }
  EXPECT_NEAR(airMass(60 * kDeg), 1.99, 0.01);
}

TEST(PreethamSky, BrightAroundTheSunBlueOverheadRedderAtLowSun) {
  const Dir3 sun{std::cos(30 * kDeg), 0, std::sin(30 * kDeg)};
  const PreethamSky sky(3.0, sun);
  const Rgb nearSun = sky.radiance({std::cos(35 * kDeg), 0, std::sin(35 * kDeg)});
  const Rgb away = sky.radiance({-std::cos(35 * kDeg), 0, std::sin(35 * kDeg)});
  const Rgb zenith = sky.radiance({0, 0, 1});
  EXPECT_GT(nearSun[1], 2 * away[1]);
  EXPECT_GT(zenith[2], zenith[0]);  // blue sky
  for (double c : zenith) EXPECT_GT(c, 0.0);
  // Zenith luminance for T = 3, sun at 30 deg elevation: Yz = 6.1649 tan(chi) + 1.7727 kcd/m^2.
  const double chi = (4.0 / 9.0 - 3.0 / 120.0) * (std::numbers::pi - 2 * 60 * kDeg);
  const double yz = (4.0453 * 3 - 4.9710) * std::tan(chi) - 0.2155 * 3 + 2.4192;
  const double Y = 0.2126 * zenith[0] + 0.7152 * zenith[1] + 0.0722 * zenith[2];
  EXPECT_NEAR(Y, yz, 0.02 * yz);
}

}  // namespace
}  // namespace vbim::lighting
