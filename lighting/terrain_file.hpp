// A terrain from a file, whatever kind it is: a georeferenced raster (a DEM: lighting/dem_reader.hpp,
// cell size and units from the file) or a picture heightmap (lighting/image_files.hpp: integer
// samples scaled to `verticalScale` metres at full scale, default 1000; float samples in metres,
// times `verticalScale` when it is given). docs/lighting.md#dem-input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lighting/georeference.hpp"
#include "lighting/procedural_terrain.hpp"
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

// Where the terrain comes from.
struct TerrainSource {
  std::string heightfield;   // single-channel image (16-bit PNG, TIFF, EXR); empty: the procedural one
  std::string albedo;        // optional colour map of the heightfield's size (the procedural terrain has its own)
  std::string bounceAlbedo;  // optional colour of the surroundings, for the bounce light only
  std::string cloudTexture;  // optional single-channel density texture; enables clouds in every variant
  // Metres between samples, and the vertical scale (metres at full scale for integer pictures, a
  // multiplier for float pictures and DEMs). A DEM's own cell size and a float file's heights are
  // used unless the matching *Given flag says the value was chosen (lighting/terrain_file.hpp).
  // The procedural terrain has its own (`procedural.cellSize`; `vbim author` and `vbim lightmap` set both).
  double cellSize = 10.0;
  double verticalScale = 1000.0;
  bool cellSizeGiven = false;
  bool verticalScaleGiven = false;
  ProceduralTerrainParams procedural;  // 512x512 by default, as `vbim lightmap`
  // Sides that are not multiples of 16 (whole macroblocks): cropped (centred), padded or left for
  // the encoder to refuse (lighting/terrain_fit.hpp). Colour maps of the heightfield file's size
  // follow the heightfield (cropped, padded, or resampled with a DEM's grid).
  TerrainFit fit = TerrainFit::Crop;
};

// The terrain as it is (no fit to whole macroblocks), with its georeferencing (a DEM's, else a local
// grid in metres) and its colour maps, which must have the terrain's size: `vbim lightmap`'s terrain.
// `fit` is ignored; a terrain file's notes (what it said, what was overridden) are in `notes`.
// Throws LightingError.
TerrainFile loadTerrainAsIs(const TerrainSource& source);

}  // namespace vbim::lighting
