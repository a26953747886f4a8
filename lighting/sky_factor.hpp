// Stewart-Langer skylight with interreflection (Hoffman & Mitchell, Game Developer 2001, Eq. 3-4;
// derivation in docs/lighting.md#sky-visibility-integral and #interreflection).
//
// The sky is split into 8 azimuth sectors centred on the 8 scanned directions (sector i spans
// (i - 1/2) pi/4 .. (i + 1/2) pi/4). In sector i the sky is visible from the zenith down to the
// horizon elevation gamma_i, clamped from below by 0 (sky above the horizontal only) and by the
// tangent plane's elevation in that direction (why: docs/lighting.md#sector-centring-and-clamps).
// The sector's irradiance from a unit-radiance sky is N . v_i with
//   v_i = 1/2 ((phi - sin 2phi / 2) dsin_i, (phi - sin 2phi / 2) dcos_i, (pi/4) sin^2 phi), phi = pi/2 - gamma_i.
// Sectors are grouped into P patches (sector i belongs to patch floor(i P / 8)); I_p sums a
// patch's sectors, K = sum_p I_p / pi, and with albedo rho the static per-texel factor is
//   S_p = I_p / (pi (1 - rho (1 - K))),   so that  E_sky = sum_p pi L_p S_p.
#pragma once

#include <cstdint>
#include <vector>

#include "lighting/horizon_scan.hpp"
#include "lighting/terrain.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::lighting {

inline constexpr int kMaxSkyPatches = 8;

int patchOfSector(int sector, int patches, int sectors = 8);  // floor(sector * patches / sectors)

// K = I / pi for one texel from its 8 horizon codes and its unit normal, with both clamps.
// `perPatch` (optional, `patches` entries) receives I_p / pi.
double skyViewFactor(const std::uint16_t codes[8], const Vec3& normal, int patches = 1, double* perPatch = nullptr);

// The same with `sectors` equal sectors (any count from 4): sector i is centred on azimuth
// i * 2 pi / sectors and the z term of v_i is (pi / sectors) sin^2 phi. More sectors follow the
// horizon more closely between the 8 grid directions (docs/lighting.md#sky-directions).
double skyViewFactorSectors(const std::uint16_t* codes, int sectors, const Vec3& normal, int patches = 1,
                            double* perPatch = nullptr);

// Horizon codes for `sectors` directions (8, 16 or 32): the 8 grid directions come from `horizons`
// exactly, the others from the per-texel ray sweep (lighting/ray_sweep.hpp) at azimuth
// i * 2 pi / sectors. One vector of width * height codes per direction.
std::vector<std::vector<std::uint16_t>> skyHorizons(const Terrain& terrain, const HorizonMaps& horizons, int sectors,
                                                    WorkerPool* pool = nullptr);

struct SkyFactors {
  int width = 0, height = 0, patches = 1;
  std::vector<float> k;       // K per texel
  std::vector<float> factor;  // S_p per texel, patch and channel: [(i * patches + p) * 3 + c]
};

SkyFactors computeSkyFactors(const Terrain& terrain, const HorizonMaps& horizons, const std::vector<Vec3>& normals,
                             int patches, WorkerPool* pool = nullptr);

// With 8, 16 or 32 sky directions (`lighting.sky_directions`); 8 is the function above.
SkyFactors computeSkyFactors(const Terrain& terrain, const HorizonMaps& horizons, const std::vector<Vec3>& normals,
                             int patches, int sectors, WorkerPool* pool = nullptr);

}  // namespace vbim::lighting
