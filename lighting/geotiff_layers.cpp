#include "lighting/geotiff_layers.hpp"

#include <system_error>

#include "lighting/error.hpp"
#include "lighting/gdal_support.hpp"

namespace vbim::lighting {

void writeGeoTiff(const std::filesystem::path& path, const FloatImage& image, const Georeference& geo,
                  const std::string& description) {
  if (image.empty() || image.channels < 1) throw LightingError(path.string() + ": nothing to write (empty layer)");
  gdal::registerDrivers();
  const gdal::QuietErrors quiet;
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (driver == nullptr) throw LightingError(path.string() + ": GDAL has no GTiff driver");
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  const char* options[] = {"COMPRESS=DEFLATE", "PREDICTOR=3", "INTERLEAVE=BAND", nullptr};
  {
    gdal::Dataset ds(driver->Create(tmp.string().c_str(), image.width, image.height, image.channels, GDT_Float32,
                                    const_cast<char**>(options)));  // GDAL's C API takes char**
    if (!ds) throw LightingError(path.string() + ": " + gdal::lastError("cannot create the GeoTIFF"));
    std::array<double, 6> gt = geo.geoTransform;
    bool ok = ds->SetGeoTransform(gt.data()) == CE_None;
    if (!geo.srsWkt.empty()) ok = ok && ds->SetProjection(geo.srsWkt.c_str()) == CE_None;
    for (int c = 0; c < image.channels && ok; ++c) {
      GDALRasterBand* band = ds->GetRasterBand(c + 1);
      band->SetDescription(description.c_str());
      // Interleaved pixels: a pixel stride of `channels` floats picks channel c.
      const auto pixelSpace = static_cast<GSpacing>(sizeof(float)) * image.channels;
      ok = band->RasterIO(GF_Write, 0, 0, image.width, image.height, const_cast<float*>(image.pixels.data()) + c,
                          image.width, image.height, GDT_Float32, pixelSpace, pixelSpace * image.width,
                          nullptr) == CE_None;
    }
    ds.reset();  // closing writes the file; GDAL 3.6 reports a failure only through its error state
    if (!ok || CPLGetLastErrorType() == CE_Failure) {
      const std::string why = gdal::lastError("cannot write the GeoTIFF");
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw LightingError(path.string() + ": " + why);
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw LightingError(path.string() + ": cannot rename the finished GeoTIFF: " + ec.message());
}

GeoTiffLayer readGeoTiff(const std::filesystem::path& path) {
  std::string why;
  const gdal::Dataset ds = gdal::openRaster(path.string(), &why);
  if (!ds) throw LightingError(path.string() + ": " + why);
  GeoTiffLayer layer;
  const int channels = ds->GetRasterCount();
  layer.image = FloatImage(ds->GetRasterXSize(), ds->GetRasterYSize(), channels);
  if (ds->GetGeoTransform(layer.geo.geoTransform.data()) != CE_None) {
    throw LightingError(path.string() + ": no geotransform");
  }
  if (const char* wkt = ds->GetProjectionRef(); wkt != nullptr) layer.geo.srsWkt = wkt;
  const gdal::QuietErrors quiet;
  for (int c = 0; c < channels; ++c) {
    GDALRasterBand* band = ds->GetRasterBand(c + 1);
    if (c == 0) layer.description = band->GetDescription();
    const auto pixelSpace = static_cast<GSpacing>(sizeof(float)) * channels;
    if (band->RasterIO(GF_Read, 0, 0, layer.image.width, layer.image.height, layer.image.pixels.data() + c,
                       layer.image.width, layer.image.height, GDT_Float32, pixelSpace, pixelSpace * layer.image.width,
                       nullptr) != CE_None) {
      throw LightingError(path.string() + ": " + gdal::lastError("cannot read the GeoTIFF"));
    }
  }
  return layer;
}

}  // namespace vbim::lighting
