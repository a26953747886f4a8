// A terrain from a file, whatever kind it is: a georeferenced raster (a DEM: lighting/dem_reader.hpp,
// cell size and units from the file) or a picture heightmap (lighting/image_files.hpp: integer
// samples scaled to `verticalScale` metres at full scale, default 1000; float samples in metres,
// times `verticalScale` when it is given). docs/lighting.md#dem-input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lighting/georeference.hpp"
#include "lighting/terrain.hpp"
#include "lighting/terrain_fit.hpp"

namespace vbim::lighting {

struct TerrainFileOptions {
  std::optional<double> cellSize;       // metres; given, it overrides a DEM's
  std::optional<double> verticalScale;  // see above
  double pictureCellSize = 10.0;        // a picture's cell size when `cellSize` is not given
  double pictureFullScale = 1000.0;     // an integer picture's full scale when `verticalScale` is not given
};

struct TerrainFile {
  Terrain terrain;
  Georeference geo;                   // the DEM's, or a local grid in metres for a picture
  bool georeferenced = false;         // true for a DEM
  std::vector<std::string> notes;     // what was read from the file and what was overridden
  int fileWidth = 0, fileHeight = 0;  // the file's own grid (a DEM's before flipping or resampling)
  GridMapping toFile;                 // the terrain's texels on the file's grid
};

TerrainFile loadTerrainFile(const std::string& path, const TerrainFileOptions& options);

}  // namespace vbim::lighting
