// Cloud shadows: a tiling density texture projected from above along the light direction and moving
// with the wind, modulating the direct (sun or moon) term only (Hoffman & Mitchell: "an additional
// texture, projected from above, which modulates the sunlight contribution").
#pragma once

#include <cstdint>

#include "lighting/float_image.hpp"
#include "lighting/sun_position.hpp"

namespace vbim::lighting {

struct CloudParams {
  bool enabled = false;
  double coverage = 0.45;                 // fraction of the sky covered, 0..1
  double opacity = 0.75;                  // direct light removed under a thick cloud, 0..1
  double scaleMetres = 4000.0;            // ground size of one tile of the texture
  double heightMetres = 1500.0;           // cloud base above the terrain, for the projection
  double windEastMetresPerHour = 1200.0;  // drift per hour of the day cycle (a time-lapse)
  double windSouthMetresPerHour = 400.0;
  std::int64_t seed = 7;
};

class CloudLayer {
 public:
  // `density` (optional, single channel, values 0..1): a texture to use instead of the procedural one.
  explicit CloudLayer(const CloudParams& p, FloatImage density = {});

  // Fraction of direct light that reaches ground point (x, y) metres (east, south) at `hours` after
  // the start, for light arriving from unit direction `light` (z up).
  float transmittance(double x, double y, double hours, const Dir3& light) const;
  // The same for texels (x0 + k, row), k = 0..count-1, of a grid of `cellSize` metres.
  void transmittanceRow(int row, int x0, int count, double cellSize, double hours, const Dir3& light, float* out) const;

  const FloatImage& density() const { return density_; }

 private:
  void textureCoords(double x, double y, double hours, const Dir3& light, double& u, double& v) const;
  float sample(double u, double v) const;

  CloudParams p_;
  FloatImage density_;
};

}  // namespace vbim::lighting
