// Digital elevation models through GDAL: GeoTIFF, ESRI ASCII grid, SRTM .hgt and anything else GDAL
// opens as a georeferenced single-band raster (https://gdal.org/drivers/raster/). Everything the
// file says is used (docs/lighting.md#dem-input):
//   - cell size from the geotransform, in metres through the SRS's linear units; for a geographic
//     SRS, metres per degree of latitude and of longitude at the DEM's centre latitude on the SRS's
//     ellipsoid (they differ: the grid is then resampled bilinearly to square cells of the smaller
//     size, and the geotransform adjusted to the new grid);
//   - heights in metres: the band's unit type (m, ft, US survey ft), else the projected SRS's linear
//     unit, else metres; the band's scale and offset applied;
//   - nodata cells (the band's nodata value, NaN) filled by GDALFillNodata's inverse-distance
//     interpolation from the nearest valid cells; a cell it cannot reach gets the lowest valid height;
//   - orientation: south-up or east-to-west grids are flipped to north-up; rotated or sheared
//     geotransforms are refused (warp them north-up first, e.g. with gdalwarp).
// Overrides are explicit and reported in `Dem::notes`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lighting/georeference.hpp"
#include "lighting/terrain.hpp"
#include "lighting/terrain_fit.hpp"

namespace vbim::lighting {

// The most cells a DEM may have, read or after resampling to square cells: 2^28 (16384 x 16384),
// 1 GiB of float heights. Larger grids are refused before any allocation.
inline constexpr std::int64_t kMaxDemCells = std::int64_t{1} << 28;
// The longest side of a DEM cell may be at most this many times its shortest (dem_reader.cpp).
inline constexpr double kMaxCellAspect = 16.0;
// A DEM's grid (in square cells) may be at most this many times longer than wide, or wide than
// long: a strip of 1,660,725 x 2 cells made from a 3-line XYZ file took the lightmap generator's
// horizon scan tens of minutes. Refused before the heights are read.
inline constexpr std::int64_t kMaxGridAspect = 256;
// At least one cell in this many must hold a height: a grid that is nearly all nodata (3 heights
// in 3.3 million cells) is refused instead of being filled for seconds into a flat terrain.
inline constexpr std::int64_t kMinValidOneIn = 1000;

struct DemOverrides {
  std::optional<double> cellSize;       // metres between texels, instead of the file's
  std::optional<double> verticalScale;  // multiplies the heights after their conversion to metres
};

struct Dem {
  Terrain terrain;
  Georeference geo;                // of the terrain's grid (after flipping and resampling)
  std::vector<std::string> notes;  // what was taken from the file and what was overridden
  // The file's own grid, and where the terrain's texels lie on it (flips and resampling undone):
  // a colour map on the file's grid follows the terrain with it (lighting/terrain_fit.hpp).
  int fileWidth = 0, fileHeight = 0;
  GridMapping toFile;
};

// True when GDAL opens `path` as a raster with a geotransform: a DEM, not a picture.
bool isGeoreferencedRaster(const std::string& path);

// Reads a DEM. Throws LightingError naming the file and what was expected.
Dem readDem(const std::string& path, const DemOverrides& overrides = {});

// Metres per degree of latitude and of longitude at geodetic latitude `latDeg` on an ellipsoid with
// semi-major axis `a` (m) and inverse flattening `invF` (0 = sphere): the meridional radius of
// curvature M and the prime-vertical radius N cos(lat), times pi / 180.
struct MetresPerDegree {
  double lat, lon;
};
MetresPerDegree metresPerDegree(double latDeg, double a, double invF);

}  // namespace vbim::lighting
