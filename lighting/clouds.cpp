#include "lighting/clouds.hpp"

#include <algorithm>
#include <cmath>

#include "lighting/error.hpp"

namespace vbim::lighting {

namespace {

constexpr int kTexture = 256;

double hash01(std::int64_t x, std::int64_t y, std::uint64_t salt) {
  std::uint64_t z = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^
                    static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4FULL ^ salt;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return static_cast<double>((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

// Tiling fBm value noise on a kTexture grid, thresholded at the coverage with a soft edge.
FloatImage proceduralDensity(const CloudParams& p) {
  FloatImage img(kTexture, kTexture, 1);
  const auto salt = static_cast<std::uint64_t>(p.seed) * 0xD1B54A32D192ED03ULL;
  std::vector<double> raw(static_cast<std::size_t>(kTexture) * kTexture);
  double lo = 1e9, hi = -1e9;
  for (int y = 0; y < kTexture; ++y) {
    for (int x = 0; x < kTexture; ++x) {
      double v = 0, amp = 0.5;
      for (int period = 4, o = 0; period <= 64; period *= 2, ++o) {
        const double fx = static_cast<double>(x) * period / kTexture, fy = static_cast<double>(y) * period / kTexture;
        const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
        double tx = fx - ix, ty = fy - iy;
        tx = tx * tx * (3 - 2 * tx);
        ty = ty * ty * (3 - 2 * ty);
        auto at = [&](std::int64_t a, std::int64_t b) { return hash01(a % period, b % period, salt + o); };
        v += amp * ((at(ix, iy) * (1 - tx) + at(ix + 1, iy) * tx) * (1 - ty) +
                    (at(ix, iy + 1) * (1 - tx) + at(ix + 1, iy + 1) * tx) * ty);
        amp *= 0.5;
      }
      raw[static_cast<std::size_t>(y) * kTexture + x] = v;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  // Threshold so that about `coverage` of the texture is cloud, with a soft 0.08-wide edge.
  std::vector<double> sorted = raw;
  std::sort(sorted.begin(), sorted.end());
  const auto cut = static_cast<std::size_t>(std::clamp(1.0 - p.coverage, 0.0, 1.0) * (sorted.size() - 1));
  const double threshold = sorted[cut], soft = 0.08 * (hi - lo);
  for (std::size_t i = 0; i < raw.size(); ++i) {
    img.pixels[i] = static_cast<float>(std::clamp((raw[i] - threshold) / soft + 0.5, 0.0, 1.0));
  }
  return img;
}

}  // namespace

CloudLayer::CloudLayer(const CloudParams& p, FloatImage density) : p_(p) {
  if (density.empty()) {
    density_ = proceduralDensity(p);
  } else {
    if (density.channels != 1) throw LightingError("cloud texture: expected a single-channel image");
    density_ = std::move(density);
  }
}

void CloudLayer::textureCoords(double x, double y, double hours, const Dir3& light, double& u, double& v) const {
  // Follow the light ray up to the cloud base; hold very low light at a 3-degree slant.
  const double lz = std::max(light.z, 0.05);
  const double wx = x + light.x / lz * p_.heightMetres - p_.windEastMetresPerHour * hours;
  const double wy = y + light.y / lz * p_.heightMetres - p_.windSouthMetresPerHour * hours;
  u = wx / p_.scaleMetres * density_.width - 0.5;
  v = wy / p_.scaleMetres * density_.height - 0.5;
  // Bring the origin back into the first tile so the per-texel arithmetic stays small.
  u -= std::floor(u / density_.width) * density_.width;
  v -= std::floor(v / density_.height) * density_.height;
}

float CloudLayer::sample(double u, double v) const {
  const double fu = std::floor(u), fv = std::floor(v);
  const double tu = u - fu, tv = v - fv;
  const int w = density_.width, h = density_.height;
  const int x0 = ((static_cast<int>(fu) % w) + w) % w, y0 = ((static_cast<int>(fv) % h) + h) % h;
  const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
  const float* d = density_.pixels.data();
  const double top = d[y0 * w + x0] * (1 - tu) + d[y0 * w + x1] * tu;
  const double bottom = d[y1 * w + x0] * (1 - tu) + d[y1 * w + x1] * tu;
  return static_cast<float>(1.0 - p_.opacity * std::clamp(top * (1 - tv) + bottom * tv, 0.0, 1.0));
}

float CloudLayer::transmittance(double x, double y, double hours, const Dir3& light) const {
  if (!p_.enabled) return 1.0f;
  double u, v;
  textureCoords(x, y, hours, light, u, v);
  return sample(u, v);
}

void CloudLayer::transmittanceRow(int row, int x0, int count, double cellSize, double hours, const Dir3& light,
                                  float* out) const {
  if (!p_.enabled) {
    std::fill(out, out + count, 1.0f);
    return;
  }
  double u, v;
  textureCoords(x0 * cellSize, row * cellSize, hours, light, u, v);
  // The texture row pair and its weight are fixed along a terrain row; walk u incrementally.
  const int w = density_.width, h = density_.height;
  const double step = cellSize / p_.scaleMetres * w;
  const double fv = std::floor(v), tv = v - fv;
  const int y0 = ((static_cast<int>(fv) % h) + h) % h, y1 = y0 + 1 == h ? 0 : y0 + 1;
  const float* top = density_.pixels.data() + static_cast<std::size_t>(y0) * w;
  const float* bottom = density_.pixels.data() + static_cast<std::size_t>(y1) * w;
  const float opacity = static_cast<float>(p_.opacity), wv = static_cast<float>(tv);
  const double wrapStep = step - std::floor(step / w) * w;  // same position modulo the tile
  double uu = u;                                            // in [0, w) (textureCoords)
  for (int x = 0; x < count; ++x) {
    const int xa = std::min(static_cast<int>(uu), w - 1), xb = xa + 1 == w ? 0 : xa + 1;
    const float tu = static_cast<float>(uu - xa);
    const float a = top[xa] + (top[xb] - top[xa]) * tu, b = bottom[xa] + (bottom[xb] - bottom[xa]) * tu;
    out[x] = 1.0f - opacity * std::clamp(a + (b - a) * wv, 0.0f, 1.0f);
    uu += wrapStep;
    if (uu >= w) uu -= w;
  }
}

}  // namespace vbim::lighting
