#include "lighting/sky_factor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "lighting/fixed_angle.hpp"
#include "lighting/ray_sweep.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr double kPi = std::numbers::pi;

// Per horizon code: A = (phi - sin 2phi / 2) / 2 and B8 = (pi / 8) sin^2 phi, phi = pi/2 - gamma
// (the z term of an eighth of the circle; a sector of 2 pi / n has B8 * 8 / n).
struct CodeTables {
  std::vector<double> a, b;
};

const CodeTables& codeTables() {
  static const CodeTables t = [] {
    CodeTables t;
    t.a.resize(65536);
    t.b.resize(65536);
    for (int c = 0; c < 65536; ++c) {
      const double phi = kPi / 2 - angleFromCode(static_cast<std::uint16_t>(c));
      t.a[c] = 0.5 * (phi - std::sin(2 * phi) / 2);
      t.b[c] = kPi / 8 * std::sin(phi) * std::sin(phi);
    }
    return t;
  }();
  return t;
}

// Per sector of n: the sector's dsin, dcos, and its centre direction.
struct Sectors {
  int n = 0;
  std::vector<double> dsin, dcos, cosAz, sinAz;
};

Sectors makeSectors(int n) {
  Sectors t;
  t.n = n;
  const double width = 2 * kPi / n;
  for (int i = 0; i < n; ++i) {
    const double a0 = (i - 0.5) * width, a1 = (i + 0.5) * width;
    t.dsin.push_back(std::sin(a1) - std::sin(a0));
    t.dcos.push_back(std::cos(a0) - std::cos(a1));
    t.cosAz.push_back(std::cos(i * width));
    t.sinAz.push_back(std::sin(i * width));
  }
  return t;
}

const Sectors& eightSectors() {
  static const Sectors t = makeSectors(8);
  return t;
}

double viewFactor(const Sectors& t, const std::uint16_t* codes, const Vec3& n, int patches, double* perPatch) {
  const CodeTables& ct = codeTables();
  const double bScale = 8.0 / t.n;
  double ip[kMaxSkyPatches] = {};
  const double nz = std::max(static_cast<double>(n.z), 1e-6);
  for (int i = 0; i < t.n; ++i) {
    // Tangent-plane elevation towards sector i: the ground itself hides everything below it.
    const double rise = -(n.x * t.cosAz[i] + n.y * t.sinAz[i]) / nz;
    const std::uint16_t c = std::max(codes[i], codeFromTangent(rise));
    ip[patchOfSector(i, patches, t.n)] +=
        n.x * ct.a[c] * t.dsin[i] + n.y * ct.a[c] * t.dcos[i] + n.z * ct.b[c] * bScale;
  }
  double k = 0;
  for (int p = 0; p < patches; ++p) {
    ip[p] = std::max(ip[p], 0.0) / kPi;
    k += ip[p];
    if (perPatch != nullptr) perPatch[p] = ip[p];
  }
  return std::min(k, 1.0);
}

}  // namespace

int patchOfSector(int sector, int patches, int sectors) {
  return sector * patches / sectors;
}

double skyViewFactor(const std::uint16_t codes[8], const Vec3& n, int patches, double* perPatch) {
  return viewFactor(eightSectors(), codes, n, patches, perPatch);
}

double skyViewFactorSectors(const std::uint16_t* codes, int sectors, const Vec3& n, int patches, double* perPatch) {
  return viewFactor(makeSectors(sectors), codes, n, patches, perPatch);
}

std::vector<std::vector<std::uint16_t>> skyHorizons(const Terrain& terrain, const HorizonMaps& h, int sectors,
                                                    WorkerPool* pool) {
  std::vector<std::vector<std::uint16_t>> codes(static_cast<std::size_t>(sectors));
  const int per = sectors / kDirections;  // sectors per grid direction
  std::vector<float> tangent;
  for (int i = 0; i < sectors; ++i) {
    if (per > 0 && i % per == 0) {
      codes[i] = h.code[i / per];
      continue;
    }
    tangent.resize(terrain.texels());
    sweepRays(terrain, i * 2 * kPi / sectors, tangent.data(), pool);
    codes[i].resize(terrain.texels());
    for (std::size_t t = 0; t < tangent.size(); ++t) codes[i][t] = codeFromTangent(tangent[t]);
  }
  return codes;
}

SkyFactors computeSkyFactors(const Terrain& terrain, const HorizonMaps& h, const std::vector<Vec3>& normals,
                             int patches, WorkerPool* pool) {
  return computeSkyFactors(terrain, h, normals, patches, kDirections, pool);
}

SkyFactors computeSkyFactors(const Terrain& terrain, const HorizonMaps& h, const std::vector<Vec3>& normals,
                             int patches, int sectors, WorkerPool* pool) {
  SkyFactors s;
  s.width = terrain.width;
  s.height = terrain.height;
  s.patches = patches;
  s.k.resize(terrain.texels());
  s.factor.resize(terrain.texels() * patches * 3);
  const Sectors table = sectors == kDirections ? eightSectors() : makeSectors(sectors);
  std::vector<std::vector<std::uint16_t>> extra;
  if (sectors != kDirections) extra = skyHorizons(terrain, h, sectors, pool);
  auto rows = [&](std::size_t row) {
    std::vector<std::uint16_t> codes(static_cast<std::size_t>(sectors));
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t i = row * terrain.width + x;
      for (int d = 0; d < sectors; ++d) codes[d] = sectors == kDirections ? h.code[d][i] : extra[d][i];
      double ip[kMaxSkyPatches];
      const double k = viewFactor(table, codes.data(), normals[i], patches, ip);
      s.k[i] = static_cast<float>(k);
      for (int c = 0; c < 3; ++c) {
        // Stewart-Langer: the terrain seen from p is lit like p itself (Hoffman & Mitchell,
        // Game Developer 2001, Eq. 3), with the bounce albedo when one is given.
        const double denom = 1.0 - terrain.bounceAlbedoAt(i, c) * (1.0 - k);
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
