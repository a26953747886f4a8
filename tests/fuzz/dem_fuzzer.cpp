// libFuzzer target: the DEM reader (GDAL) on any bytes. The first byte picks the file name's
// extension (GeoTIFF, ESRI ASCII grid, SRTM .hgt, XYZ), the rest is the file, served from GDAL's
// in-memory file system. readDem may refuse the file with LightingError; any other exception, crash
// or sanitizer report is a finding. A DEM it accepts must have a usable grid.
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "lighting/dem_reader.hpp"
#include "lighting/error.hpp"

namespace {

constexpr std::array<const char*, 4> kExtensions{".tif", ".asc", ".hgt", ".xyz"};

void checkAccepted(const vbim::lighting::Dem& dem) {
  const vbim::lighting::Terrain& t = dem.terrain;
  if (t.width <= 0 || t.height <= 0 || t.heights.size() != t.texels()) std::abort();
  if (!(t.cellSize > 0) || !std::isfinite(t.cellSize) || !(t.heightStep > 0)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  CPLSetErrorHandler(CPLQuietErrorHandler);      // GDAL's warnings would flood the fuzzer's log
  CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml side files
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string path = std::string("/vsimem/dem") + kExtensions[data[0] % kExtensions.size()];
  VSILFILE* file = VSIFileFromMemBuffer(path.c_str(), const_cast<GByte*>(data + 1), size - 1, FALSE);
  if (file == nullptr) return 0;
  VSIFCloseL(file);
  try {
    checkAccepted(vbim::lighting::readDem(path));
    checkAccepted(vbim::lighting::readDem(path, {.cellSize = 2.5, .verticalScale = 3.0}));
  } catch (const vbim::lighting::LightingError&) {
    // refused with a message naming the file: expected for most inputs
  }
  VSIUnlink(path.c_str());
  return 0;
}
