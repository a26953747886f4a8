// Small helpers around GDAL shared by the DEM reader and the GeoTIFF writer: drivers registered
// once, datasets closed by RAII, GDAL's own error text caught instead of printed.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>

namespace vbim::lighting::gdal {

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(GDALDataset::ToHandle(d)); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

// Registers GDAL's drivers (once, thread-safe).
void registerDrivers();

// Opens `path` read-only as a raster, or returns null (GDAL's message in `why`). Nothing is printed.
Dataset openRaster(const std::string& path, std::string* why = nullptr);

// GDAL's last error message, or `fallback` when it left none.
std::string lastError(const std::string& fallback);

// While alive, GDAL's errors and warnings are kept (CPLGetLastErrorMsg) instead of printed.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
};

}  // namespace vbim::lighting::gdal
