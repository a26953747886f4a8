#include "lighting/terrain_file.hpp"

#include "lighting/dem_reader.hpp"
#include "lighting/image_files.hpp"

namespace vbim::lighting {

TerrainFile loadTerrainFile(const std::string& path, const TerrainFileOptions& options) {
  TerrainFile f;
  if (isGeoreferencedRaster(path)) {
    Dem dem = readDem(path, {options.cellSize, options.verticalScale});
    f.terrain = std::move(dem.terrain);
    f.geo = std::move(dem.geo);
    f.georeferenced = true;
    f.notes = std::move(dem.notes);
    f.fileWidth = dem.fileWidth;
    f.fileHeight = dem.fileHeight;
    f.toFile = dem.toFile;
    return f;
  }
  const double cell = options.cellSize.value_or(options.pictureCellSize);
  const bool floats = heightfieldHasFloatSamples(path);
  // Float samples are heights in metres: they are not scaled unless asked (a DEM written as a plain
  // float picture stays the right height).
  const double scale = options.verticalScale.value_or(floats ? 1.0 : options.pictureFullScale);
  f.terrain = readHeightfield(path, cell, scale);
  f.geo = localGrid(cell);
  f.fileWidth = f.terrain.width;
  f.fileHeight = f.terrain.height;
  if (floats && options.verticalScale) f.notes.push_back("float heights multiplied by --vertical-scale");
  return f;
}

}  // namespace vbim::lighting

namespace vbim::lighting {

TerrainFile loadTerrainAsIs(const TerrainSource& src) {
  TerrainFile f;
  if (src.heightfield.empty()) {
    f.terrain = proceduralTerrain(src.procedural);
    if (src.albedo.empty()) setAlbedo(f.terrain, proceduralAlbedo(f.terrain), "procedural albedo");
    f.geo = localGrid(src.procedural.cellSize);
  } else {
    TerrainFileOptions options;
    options.pictureCellSize = src.cellSize;
    options.pictureFullScale = src.verticalScale;
    if (src.cellSizeGiven) options.cellSize = src.cellSize;
    if (src.verticalScaleGiven) options.verticalScale = src.verticalScale;
    f = loadTerrainFile(src.heightfield, options);
  }
  if (!src.albedo.empty()) setAlbedo(f.terrain, readColourMap(src.albedo), src.albedo);
  if (!src.bounceAlbedo.empty()) setBounceAlbedo(f.terrain, readColourMap(src.bounceAlbedo), src.bounceAlbedo);
  return f;
}

}  // namespace vbim::lighting
