#include "streams/authoring/synthetic_day.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "streams/authoring/error.hpp"

namespace vbim::streams {

namespace {

constexpr double kPi = std::numbers::pi;

struct Sun {
  double dir[3];     // towards the sun, z up
  double elevation;  // radians
  double colour[3];  // linear RGB irradiance
  double sky[3];     // ambient sky colour
  double penumbra;   // angular half-width of the shadow edge, radians
};

bool overcast(const SyntheticDay& d) {
  return d.weather == "overcast";
}

// The sun of frame `f`: frame 0 is midnight, frames/2 is noon; it rises in the east (+x) and sets in
// the west, 60 degrees high at noon, 30 degrees below the horizon at midnight.
Sun sunAt(const SyntheticDay& d, std::uint32_t f) {
  const double t = static_cast<double>(f) / d.frames;  // 0..1 over the day
  const double hour = 2 * kPi * t;
  Sun s{};
  s.elevation = -std::cos(hour) * (kPi / 3.0 + kPi / 6.0) / 2 + (kPi / 3.0 - kPi / 6.0) / 2;
  const double azimuth = hour - kPi / 2;  // east at 6:00, south at noon, west at 18:00
  s.dir[0] = std::cos(s.elevation) * std::cos(azimuth + kPi / 2);
  s.dir[1] = std::cos(s.elevation) * std::sin(azimuth + kPi / 2) * 0.6 - 0.3;
  s.dir[2] = std::sin(s.elevation);
  const double n = std::sqrt(s.dir[0] * s.dir[0] + s.dir[1] * s.dir[1] + s.dir[2] * s.dir[2]);
  for (double& c : s.dir) c /= n;
  // Daylight fades in over the last 6 degrees below the horizon; low sun turns orange.
  const double day = std::clamp((s.elevation + 0.1) / 0.3, 0.0, 1.0);
  const double warm = std::clamp(1.0 - s.elevation / 0.5, 0.0, 1.0);
  const double sunScale = overcast(d) ? 0.25 : 1.6;
  s.colour[0] = sunScale * day * 1.0;
  s.colour[1] = sunScale * day * (0.95 - 0.35 * warm);
  s.colour[2] = sunScale * day * (0.90 - 0.60 * warm);
  const double skyScale = overcast(d) ? 0.55 : 0.35;
  const double night = 0.03;
  s.sky[0] = night * 0.5 + skyScale * day * (overcast(d) ? 0.85 : 0.55);
  s.sky[1] = night * 0.6 + skyScale * day * (overcast(d) ? 0.87 : 0.70);
  s.sky[2] = night * 1.0 + skyScale * day * (overcast(d) ? 0.90 : 1.00);
  s.penumbra = overcast(d) ? 0.35 : 0.06;
  return s;
}

// Smooth terrain: a sum of a few low-frequency bumps, in texel units of height.
double heightAt(const SyntheticDay& d, double x, double y) {
  const double u = x / d.width, v = y / d.height;
  return d.width * (0.06 * std::sin(2 * kPi * (1.0 * u + 0.3)) * std::cos(2 * kPi * (0.8 * v - 0.1)) +
                    0.04 * std::sin(2 * kPi * (2.1 * u + 1.7 * v)) + 0.025 * std::cos(2 * kPi * (3.3 * v - 2.2 * u)) +
                    0.05 * std::exp(-((u - 0.6) * (u - 0.6) + (v - 0.4) * (v - 0.4)) / 0.01));
}

}  // namespace

void checkSyntheticDay(const SyntheticDay& d) {
  if (d.weather != "clear" && d.weather != "overcast")
    throw AuthoringError("synthetic weather '" + d.weather + "': expected clear or overcast");
  if (d.width < 16 || d.height < 16 || d.frames == 0)
    throw AuthoringError("synthetic day: sizes must be at least 16 and frames at least 1");
}

FloatRgbImage syntheticLightmap(const SyntheticDay& d, std::uint32_t frame) {
  checkSyntheticDay(d);
  const Sun sun = sunAt(d, frame);
  std::vector<double> h(static_cast<std::size_t>(d.width) * d.height);
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) h[static_cast<std::size_t>(y) * d.width + x] = heightAt(d, x, y);
  auto hAt = [&](double x, double y) {
    if (x < 0 || y < 0 || x > d.width - 1 || y > d.height - 1) return heightAt(d, x, y);
    return h[static_cast<std::size_t>(std::lround(y)) * d.width + static_cast<std::size_t>(std::lround(x))];
  };
  const double horiz = std::hypot(sun.dir[0], sun.dir[1]);
  const double sx = horiz > 0 ? sun.dir[0] / horiz : 0, sy = horiz > 0 ? sun.dir[1] / horiz : 0;
  FloatRgbImage out(d.width, d.height);
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      const double h0 = hAt(x, y);
      const double dx = (hAt(x + 1, y) - hAt(x - 1, y)) / 2, dy = (hAt(x, y + 1) - hAt(x, y - 1)) / 2;
      const double nl = std::sqrt(dx * dx + dy * dy + 1);
      const double n[3] = {-dx / nl, -dy / nl, 1 / nl};
      // Horizon angle towards the sun's azimuth: march with growing steps.
      double horizon = -kPi / 2;
      for (double r = 1.5; r < d.width * 0.75; r *= 1.35) {
        const double rise = hAt(x + sx * r, y + sy * r) - h0;
        horizon = std::max(horizon, std::atan2(rise, r));
      }
      const double lit = std::clamp((sun.elevation - horizon) / (2 * sun.penumbra) + 0.5, 0.0, 1.0);
      const double shadow = lit * lit * (3 - 2 * lit);  // smoothstep: a soft edge
      const double ndotl = std::max(0.0, n[0] * sun.dir[0] + n[1] * sun.dir[1] + n[2] * sun.dir[2]);
      const double skyView = 0.5 + 0.5 * n[2];
      float* px = out.at(x, y);
      for (int c = 0; c < 3; ++c) px[c] = static_cast<float>(sun.colour[c] * ndotl * shadow + sun.sky[c] * skyView);
    }
  }
  return out;
}

FloatRgbImage syntheticSky(const SyntheticDay& d, std::uint32_t frame) {
  checkSyntheticDay(d);
  const Sun sun = sunAt(d, frame);
  FloatRgbImage out(d.skyWidth, d.skyHeight);
  for (int y = 0; y < d.skyHeight; ++y) {
    const double elev = (1.0 - (y + 0.5) / d.skyHeight) * kPi / 2;  // top row: zenith
    for (int x = 0; x < d.skyWidth; ++x) {
      const double az = 2 * kPi * (x + 0.5) / d.skyWidth;
      const double v[3] = {std::cos(elev) * std::cos(az), std::cos(elev) * std::sin(az), std::sin(elev)};
      const double cosToSun = v[0] * sun.dir[0] + v[1] * sun.dir[1] + v[2] * sun.dir[2];
      const double glow = overcast(d) ? 0.3 * std::pow(std::max(0.0, cosToSun), 4)
                                      : 0.8 * std::pow(std::max(0.0, cosToSun), 24) + 0.2 * std::max(0.0, cosToSun);
      const double horizonBand = std::exp(-elev * 4);
      float* px = out.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const double base = sun.sky[c] * (overcast(d) ? 1.2 : 1.0 + 0.8 * horizonBand * (c == 2 ? 0.3 : 1.0));
        px[c] = static_cast<float>(base * 1.6 + sun.colour[c] * glow);
      }
    }
  }
  return out;
}

}  // namespace vbim::streams
