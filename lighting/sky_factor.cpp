#include "lighting/sky_factor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "lighting/fixed_angle.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr double kPi = std::numbers::pi;

struct Tables {
  // Per horizon code: A = (phi - sin 2phi / 2) / 2 and B = (pi / 8) sin^2 phi, phi = pi/2 - gamma.
  std::vector<double> a, b;
  std::array<double, 8> dsin{}, dcos{}, cosAz{}, sinAz{};
};

const Tables& tables() {
  static const Tables t = [] {
    Tables t;
    t.a.resize(65536);
    t.b.resize(65536);
    for (int c = 0; c < 65536; ++c) {
      const double phi = kPi / 2 - angleFromCode(static_cast<std::uint16_t>(c));
      t.a[c] = 0.5 * (phi - std::sin(2 * phi) / 2);
      t.b[c] = kPi / 8 * std::sin(phi) * std::sin(phi);
    }
    for (int i = 0; i < 8; ++i) {
      const double a0 = (i - 0.5) * kPi / 4, a1 = (i + 0.5) * kPi / 4;
      t.dsin[i] = std::sin(a1) - std::sin(a0);
      t.dcos[i] = std::cos(a0) - std::cos(a1);
      t.cosAz[i] = std::cos(i * kPi / 4);
      t.sinAz[i] = std::sin(i * kPi / 4);
    }
    return t;
  }();
  return t;
}

}  // namespace

int patchOfSector(int sector, int patches) {
  return sector * patches / 8;
}

double skyViewFactor(const std::uint16_t codes[8], const Vec3& n, int patches, double* perPatch) {
  const Tables& t = tables();
  double ip[kMaxSkyPatches] = {};
  const double nz = std::max(static_cast<double>(n.z), 1e-6);
  for (int i = 0; i < 8; ++i) {
    // Tangent-plane elevation towards sector i: the ground itself hides everything below it.
    const double rise = -(n.x * t.cosAz[i] + n.y * t.sinAz[i]) / nz;
    const std::uint16_t c = std::max(codes[i], codeFromTangent(rise));
    ip[patchOfSector(i, patches)] += n.x * t.a[c] * t.dsin[i] + n.y * t.a[c] * t.dcos[i] + n.z * t.b[c];
  }
  double k = 0;
  for (int p = 0; p < patches; ++p) {
    ip[p] = std::max(ip[p], 0.0) / kPi;
    k += ip[p];
    if (perPatch != nullptr) perPatch[p] = ip[p];
  }
  return std::min(k, 1.0);
}

SkyFactors computeSkyFactors(const Terrain& terrain, const HorizonMaps& h, const std::vector<Vec3>& normals,
                             int patches, WorkerPool* pool) {
  SkyFactors s;
  s.width = terrain.width;
  s.height = terrain.height;
  s.patches = patches;
  s.k.resize(terrain.texels());
  s.factor.resize(terrain.texels() * patches * 3);
  auto rows = [&](std::size_t row) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t i = row * terrain.width + x;
      std::uint16_t codes[8];
      for (int d = 0; d < 8; ++d) codes[d] = h.code[d][i];
      double ip[kMaxSkyPatches];
      const double k = skyViewFactor(codes, normals[i], patches, ip);
      s.k[i] = static_cast<float>(k);
      for (int c = 0; c < 3; ++c) {
        // Stewart-Langer: the terrain seen from p is lit like p itself (Hoffman & Mitchell,
        // Game Developer 2001, Eq. 3).
        const double denom = 1.0 - terrain.albedoAt(i, c) * (1.0 - k);
        for (int p = 0; p < patches; ++p) s.factor[(i * patches + p) * 3 + c] = static_cast<float>(ip[p] / denom);
      }
    }
  };
  if (pool != nullptr) {
    pool->parallelFor(static_cast<std::size_t>(terrain.height), rows);
  } else {
    for (int y = 0; y < terrain.height; ++y) rows(static_cast<std::size_t>(y));
  }
  return s;
}

}  // namespace vbim::lighting
