// Debug layers and lightmaps as GeoTIFF with the terrain's georeferencing, so GIS tools (QGIS,
// GRASS, SAGA, gdalinfo) open them aligned with the DEM they came from. Float32 samples, one band
// per channel, DEFLATE-compressed; written under a temporary name, then renamed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lighting/float_image.hpp"
#include "lighting/georeference.hpp"

namespace vbim::lighting {

// `description` names the layer (the TIFF's band description), e.g. "sky factor K".
void writeGeoTiff(const std::filesystem::path& path, const FloatImage& image, const Georeference& geo,
                  const std::string& description);

// Reads back what writeGeoTiff wrote (first band only when `channels` is 1): for tests and tools.
struct GeoTiffLayer {
  FloatImage image;
  Georeference geo;
  std::string description;
};
GeoTiffLayer readGeoTiff(const std::filesystem::path& path);

}  // namespace vbim::lighting
