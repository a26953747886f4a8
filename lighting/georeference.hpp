// Where a terrain grid lies on the Earth, as GDAL describes a raster: the affine geotransform
// (x = gt[0] + col * gt[1] + row * gt[2], y = gt[3] + col * gt[4] + row * gt[5], at pixel corners) and the
// spatial reference system as WKT (https://gdal.org/tutorials/geotransforms_tut.html).
#pragma once

#include <array>
#include <string>

namespace vbim::lighting {

struct Georeference {
  std::array<double, 6> geoTransform{0, 1, 0, 0, 0, -1};
  std::string srsWkt;  // empty: no spatial reference (a local grid in metres)
};

// A local north-up grid with `cellSize` metres per texel and its top-left corner at (0, 0), for
// terrains that came without georeferencing (pictures, the procedural terrain).
inline Georeference localGrid(double cellSize) {
  return {{0, cellSize, 0, 0, 0, -cellSize}, {}};
}

}  // namespace vbim::lighting
