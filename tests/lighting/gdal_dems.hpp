// Small DEMs written with GDAL itself (not with the code under test), for the DEM reader, GeoTIFF
// layer and command-line tests: any driver GDAL can create a copy with (GTiff, AAIGrid, SRTMHGT).
#pragma once

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace vbim::lighting::testing {

struct DemSpec {
  int width = 8, height = 8;
  std::vector<float> values;                    // row-major, width * height
  std::array<double, 6> gt{0, 1, 0, 0, 0, -1};  // geotransform
  int epsg = 0;                                 // 0: no spatial reference
  std::string unit;                             // band unit type ("" = none)
  bool hasNodata = false;
  double nodata = -9999;
  GDALDataType type = GDT_Float32;
};

// Writes `spec` to `path` with GDAL's `driver` (through an in-memory dataset and CreateCopy).
inline void writeDem(const std::filesystem::path& path, const DemSpec& spec, const char* driver = "GTiff") {
  GDALAllRegister();
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDataset* src = mem->Create("", spec.width, spec.height, 1, spec.type, nullptr);
  ASSERT_NE(src, nullptr);
  std::array<double, 6> gt = spec.gt;
  src->SetGeoTransform(gt.data());
  if (spec.epsg != 0) {
    OGRSpatialReference srs;
    ASSERT_EQ(srs.importFromEPSG(spec.epsg), OGRERR_NONE);
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    src->SetSpatialRef(&srs);
  }
  GDALRasterBand* band = src->GetRasterBand(1);
  if (!spec.unit.empty()) band->SetUnitType(spec.unit.c_str());
  if (spec.hasNodata) band->SetNoDataValue(spec.nodata);
  std::vector<float> values = spec.values;
  ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, spec.width, spec.height, values.data(), spec.width, spec.height, GDT_Float32,
                           0, 0, nullptr),
            CE_None);
  GDALDriver* out = GetGDALDriverManager()->GetDriverByName(driver);
  ASSERT_NE(out, nullptr);
  GDALDataset* copy = out->CreateCopy(path.string().c_str(), src, FALSE, nullptr, nullptr, nullptr);
  ASSERT_NE(copy, nullptr) << CPLGetLastErrorMsg();
  GDALClose(copy);
  GDALClose(src);
}

}  // namespace vbim::lighting::testing
