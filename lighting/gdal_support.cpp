#include "lighting/gdal_support.hpp"

#include <cpl_error.h>

#include <mutex>

namespace vbim::lighting::gdal {

void registerDrivers() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

QuietErrors::QuietErrors() {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
}

QuietErrors::~QuietErrors() {
  CPLPopErrorHandler();
}

std::string lastError(const std::string& fallback) {
  const char* msg = CPLGetLastErrorMsg();
  return msg != nullptr && *msg != '\0' ? std::string(msg) : fallback;
}

Dataset openRaster(const std::string& path, std::string* why) {
  registerDrivers();
  const QuietErrors quiet;
  Dataset d(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!d && why != nullptr) *why = lastError("GDAL does not recognise it as a raster");
  return d;
}

}  // namespace vbim::lighting::gdal
