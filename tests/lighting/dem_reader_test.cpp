// DEMs through GDAL (lighting/dem_reader.hpp, lighting/terrain_file.hpp): cell size, units, nodata,
// orientation and geographic coordinates taken from the file; overrides explicit; picture
// heightmaps as before (integer ones scaled, float ones in metres). Inputs are written with GDAL
// directly, plus a real excerpt (tests/lighting/data/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "lighting/dem_reader.hpp"
#include "lighting/error.hpp"
#include "lighting/geotiff_layers.hpp"
#include "lighting/terrain_file.hpp"
#include "tests/lighting/gdal_dems.hpp"
#include "tests/lighting/oiio_scratch.hpp"

namespace vbim::lighting {
namespace {

namespace fs = std::filesystem;
using testing::DemSpec;
using testing::RemoveScratch;
using testing::scratch;
using testing::writeDem;
const auto* const kRemoveScratch = ::testing::AddGlobalTestEnvironment(new RemoveScratch);

std::vector<float> ramp(int w, int h, double base, double perCol, double perRow) {
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      v[static_cast<std::size_t>(y) * w + x] = static_cast<float>(base + perCol * x + perRow * y);
  return v;
}

bool mentions(const std::vector<std::string>& notes, const std::string& text) {
  return std::any_of(notes.begin(), notes.end(),
                     [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

TEST(DemReader, ProjectedMetresNeedNoOptions) {
  DemSpec s;
  s.width = 6;
  s.height = 5;
  s.values = ramp(6, 5, 1200.0, 3.5, -2.0);
  s.gt = {500000, 30, 0, 5000000, 0, -30};
  s.epsg = 32632;  // UTM 32N, metres
  const fs::path p = scratch("utm.tif");
  writeDem(p, s);
  const TerrainFile f = loadTerrainFile(p.string(), {});
  ASSERT_TRUE(f.georeferenced);
  EXPECT_DOUBLE_EQ(f.terrain.cellSize, 30.0);
  ASSERT_EQ(f.terrain.width, 6);
  ASSERT_EQ(f.terrain.height, 5);
  for (std::size_t i = 0; i < s.values.size(); ++i)
    EXPECT_NEAR(f.terrain.heights[i] * f.terrain.heightStep, s.values[i], 1.0 / 256);
  EXPECT_EQ(f.geo.geoTransform, s.gt);
  EXPECT_NE(f.geo.srsWkt.find("32N"), std::string::npos) << f.geo.srsWkt;
  EXPECT_TRUE(mentions(f.notes, "cell size 30 m from the file"));
}

TEST(DemReader, FeetFromTheBandUnitAndOverridesArePrinted) {
  DemSpec s;
  s.width = s.height = 4;
  s.values = ramp(4, 4, 1000.0, 10.0, 0.0);
  s.gt = {0, 100, 0, 0, 0, -100};
  s.epsg = 32632;
  s.unit = "ft";
  const fs::path p = scratch("feet.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  EXPECT_NEAR(dem.terrain.metresAt(1, 0), 1010.0 * 0.3048, 1.0 / 256);
  const Dem scaled = readDem(p.string(), {.cellSize = 25.0, .verticalScale = 2.0});
  EXPECT_DOUBLE_EQ(scaled.terrain.cellSize, 25.0);
  EXPECT_NEAR(scaled.terrain.metresAt(1, 0), 2 * 1010.0 * 0.3048, 1.0 / 128);
  EXPECT_TRUE(mentions(scaled.notes, "cell size 25 m (--cell-size) instead of the file's 100 m"));
  EXPECT_TRUE(mentions(scaled.notes, "multiplied by 2 (--vertical-scale)"));
}

TEST(DemReader, ProjectedFeetSrsScalesCellsAndHeights) {
  DemSpec s;
  s.width = s.height = 4;
  s.values = std::vector<float>(16, 100.0f);
  s.gt = {6000000, 10, 0, 2000000, 0, -10};
  s.epsg = 2227;  // NAD83 / California zone 3, US survey feet
  const fs::path p = scratch("ftus.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  EXPECT_NEAR(dem.terrain.cellSize, 10 * 1200.0 / 3937, 1e-9);
  EXPECT_NEAR(dem.terrain.metresAt(0, 0), 100 * 1200.0 / 3937, 1.0 / 256);
}

// Metres per degree by the usual series for WGS84 (an independent check of the ellipsoid formula).
TEST(DemReader, GeographicCellsAreMetresAtTheCentreLatitude) {
  for (double lat : {0.0, 30.0, 45.0, 60.0}) {
    const MetresPerDegree m = metresPerDegree(lat, 6378137.0, 298.257223563);
    const double r = lat * std::numbers::pi / 180;
    const double latSeries = 111132.92 - 559.82 * std::cos(2 * r) + 1.175 * std::cos(4 * r) - 0.0023 * std::cos(6 * r);
    const double lonSeries = 111412.84 * std::cos(r) - 93.5 * std::cos(3 * r) + 0.118 * std::cos(5 * r);
    EXPECT_NEAR(m.lat, latSeries, 0.05) << lat;
    EXPECT_NEAR(m.lon, lonSeries, 0.05) << lat;
  }
  DemSpec s;
  s.width = 20;
  s.height = 10;
  s.values = ramp(20, 10, 300.0, 0.0, 1.0);  // one metre per row, rising southwards
  const double arcsec = 1.0 / 3600;
  s.gt = {7.0, arcsec, 0, 45.0 + 5 * arcsec, 0, -arcsec};  // centred on 45 N
  s.epsg = 4326;
  const fs::path p = scratch("geographic.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  const MetresPerDegree m = metresPerDegree(45.0, 6378137.0, 298.257223563);
  const double dx = arcsec * m.lon, dy = arcsec * m.lat;  // 21.9 m and 30.9 m
  EXPECT_NEAR(dem.terrain.cellSize, dx, 1e-6);
  EXPECT_EQ(dem.terrain.width, 20);
  EXPECT_EQ(dem.terrain.height, static_cast<int>(std::lround(10 * dy / dx)));  // 14 square rows
  // The same extent, finer rows; the slope per metre southwards is kept (1 m per dy metres).
  EXPECT_NEAR(dem.geo.geoTransform[5] * dem.terrain.height, -10 * arcsec, 1e-12);
  const double slope = (dem.terrain.metresAt(5, 9) - dem.terrain.metresAt(5, 4)) / (5 * dem.terrain.cellSize);
  EXPECT_NEAR(slope, 1.0 / dy, 2e-3);  // one metre per row of dy metres
  EXPECT_TRUE(mentions(dem.notes, "geographic coordinates"));
}

TEST(DemReader, NodataIsFilledFromTheNeighboursAndAnAsciiGridReads) {
  DemSpec s;
  s.width = s.height = 7;
  s.values = ramp(7, 7, 50.0, 1.0, 0.0);
  s.gt = {1000, 5, 0, 2000, 0, -5};
  s.hasNodata = true;
  s.nodata = -9999;
  for (int i : {24, 25, 31}) s.values[static_cast<std::size_t>(i)] = -9999;  // a hole in the middle
  const fs::path p = scratch("holes.asc");
  writeDem(p, s, "AAIGrid");
  const Dem dem = readDem(p.string());
  EXPECT_DOUBLE_EQ(dem.terrain.cellSize, 5.0);
  for (int i : {24, 25, 31}) {
    const double h = dem.terrain.heights[static_cast<std::size_t>(i)] * dem.terrain.heightStep;
    EXPECT_GE(h, 50.0) << i;  // within the valid range around it: no pit, no spike
    EXPECT_LE(h, 56.0) << i;
  }
  EXPECT_TRUE(mentions(dem.notes, "3 nodata cells filled"));
  DemSpec all = s;
  std::fill(all.values.begin(), all.values.end(), -9999.0f);
  writeDem(scratch("void.asc"), all, "AAIGrid");
  EXPECT_THROW(readDem(scratch("void.asc").string()), LightingError);
}

TEST(DemReader, HugeOrNonFiniteGridsAreRefusedFromTheHeader) {
  // An ASCII grid whose header claims 20000 x 20000 cells (4e8, above kMaxDemCells) over one row.
  const fs::path huge = scratch("huge.asc");
  {
    std::ofstream out(huge);
    out << "ncols 20000\nnrows 20000\nxllcorner 0\nyllcorner 0\ncellsize 30\n1 2 3\n";
  }
  try {
    readDem(huge.string());
    FAIL() << "a 20000x20000 grid was accepted";
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.asc: the DEM is 20000x20000 cells, more than the 268435456"),
              std::string::npos)
        << e.what();
  }
  // A geographic grid at the pole: at 89.99 degrees, cells of 0.001 degrees are ~0.02 m east-west
  // and ~111 m north-south, so square cells would need ~5,700 times as many rows (4000 x ~114,000).
  // Refused, not resampled.
  DemSpec s;
  s.width = 4000;
  s.height = 20;
  s.values.assign(static_cast<std::size_t>(s.width) * s.height, 10.0f);
  s.gt = {0, 0.001, 0, 90.0, 0, -0.001};
  s.epsg = 4326;
  const fs::path polar = scratch("polar.tif");
  writeDem(polar, s);
  try {
    readDem(polar.string());
    FAIL() << "a resampled grid above the limit was accepted";
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the 268435456 vbim reads; crop the DEM or give --cell-size"),
              std::string::npos)
        << e.what();
  }
}

// Cells far longer one way than the other are refused rather than resampled: a damaged header
// (found by dem_fuzzer: 1 x 6,444,444 m cells) asked for millions of square cells from three.
TEST(DemReader, DegenerateCellsAreRefusedNotResampled) {
  DemSpec s;
  s.width = 2;
  s.height = 3;
  s.values = ramp(2, 3, 10.0, 1.0, 1.0);
  s.gt = {0, 1, 0, 0, 0, -17};  // 1 x 17 m: just past the limit
  writeDem(scratch("thin.tif"), s);
  try {
    readDem(scratch("thin.tif").string());
    FAIL() << "cells of 1 x 17 m were resampled";
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("thin.tif: cells of 1 x 17 m are more than 16 times longer one way"),
              std::string::npos)
        << e.what();
  }
  s.gt = {0, 1, 0, 0, 0, -16};  // at the limit: resampled to 2 x 48 square cells of 1 m
  writeDem(scratch("long.tif"), s);
  const Dem dem = readDem(scratch("long.tif").string());
  EXPECT_EQ(dem.terrain.width, 2);
  EXPECT_EQ(dem.terrain.height, 48);
}

TEST(DemReader, SouthUpIsFlippedAndRotatedIsRefused) {
  DemSpec s;
  s.width = 3;
  s.height = 4;
  s.values = ramp(3, 4, 10.0, 0.0, 10.0);  // row 0 (the south edge here) lowest
  s.gt = {0, 10, 0, 0, 0, 10};             // rows go north
  const fs::path p = scratch("southup.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  EXPECT_NEAR(dem.terrain.metresAt(0, 0), 40.0, 1.0 / 256);  // the north edge is row 0 now
  EXPECT_NEAR(dem.terrain.metresAt(0, 3), 10.0, 1.0 / 256);
  EXPECT_EQ(dem.geo.geoTransform[3], 40.0);
  EXPECT_EQ(dem.geo.geoTransform[5], -10.0);

  s.gt = {0, 10, 2, 0, 1, -10};
  writeDem(scratch("rotated.tif"), s);
  try {
    readDem(scratch("rotated.tif").string());
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("rotated.tif: the DEM's grid is rotated or sheared"), std::string::npos)
        << e.what();
  }
}

TEST(DemReader, SrtmHgtTileReads) {
  DemSpec s;
  s.width = s.height = 1201;  // SRTM-3: 3 arc-seconds, one degree
  s.values.assign(static_cast<std::size_t>(s.width) * s.height, 0.0f);
  for (int x = 0; x < s.width; ++x) s.values[600 * 1201 + x] = 700.0f;  // a ridge along the 45.5 N parallel
  const double step = 1.0 / 1200;
  s.gt = {6.0 - step / 2, step, 0, 46.0 + step / 2, 0, -step};
  s.epsg = 4326;
  s.type = GDT_Int16;
  const fs::path p = scratch("N45E006.hgt");
  writeDem(p, s, "SRTMHGT");
  const Dem dem = readDem(p.string());
  const MetresPerDegree m = metresPerDegree(45.5, 6378137.0, 298.257223563);
  EXPECT_NEAR(dem.terrain.cellSize, step * m.lon, 1e-6);
  EXPECT_EQ(dem.terrain.width, 1201);
  EXPECT_EQ(dem.terrain.height, static_cast<int>(std::lround(1201 * m.lat / m.lon)));
  // The ridge stays on the 45.5 N parallel: the highest of column 100 is where row 600 of 1201 maps.
  int top = 0;
  for (int y = 1; y < dem.terrain.height; ++y)
    if (dem.terrain.at(100, y) > dem.terrain.at(100, top)) top = y;
  EXPECT_NEAR(top + 0.5, 600.5 * dem.terrain.height / 1201.0, 1.0);
  EXPECT_GT(dem.terrain.metresAt(100, top), 350.0);  // bilinear rows around a one-row ridge
  EXPECT_NEAR(dem.terrain.metresAt(100, 0), 0.0, 1.0 / 256);
}

// A colour map on the file's grid lands where the terrain's texels are: sampled through
// `Dem::toFile`, the file's own values give the terrain's heights back (the reader flips and
// resamples them the same way), on a geographic grid stored south-up and east to west.
TEST(DemReader, TheFileGridMappingUndoesFlipsAndResampling) {
  DemSpec s;
  s.width = 12;
  s.height = 7;
  s.values.resize(12 * 7);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 12; ++x) s.values[static_cast<std::size_t>(y) * 12 + x] = static_cast<float>(x * x + 7 * y);
  const double arcsec = 1.0 / 3600;
  s.gt = {7.0 + 12 * arcsec, -arcsec, 0, 45.0, 0, arcsec};  // east to west, south-up
  s.epsg = 4326;
  const fs::path p = scratch("flipped_geographic.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  EXPECT_EQ(dem.fileWidth, 12);
  EXPECT_EQ(dem.fileHeight, 7);
  ASSERT_NE(dem.terrain.height, 7);  // resampled to square cells
  FloatImage file(12, 7, 1);
  file.pixels = s.values;
  const FloatImage onTerrain = resampleImage(file, dem.toFile, dem.terrain.width, dem.terrain.height);
  for (int y = 0; y < dem.terrain.height; ++y)
    for (int x = 0; x < dem.terrain.width; ++x)
      ASSERT_NEAR(onTerrain.at(x, y)[0], dem.terrain.metresAt(x, y), 1.0 / 256) << x << ", " << y;
}

// The interpolation looks at most 100 cells away (GDAL's default): a cell farther than that from
// every valid cell takes the lowest valid height, and a sparse grid is filled in bounded time.
TEST(DemReader, NodataFarFromEveryValidCellTakesTheLowestHeight) {
  DemSpec s;
  s.width = 301;
  s.height = 3;
  s.values.assign(static_cast<std::size_t>(s.width) * s.height, -9999.0f);
  s.gt = {1000, 5, 0, 2000, 0, -5};
  s.hasNodata = true;
  s.nodata = -9999;
  for (int y = 0; y < s.height; ++y) {
    s.values[static_cast<std::size_t>(y) * s.width] = 100.0f;        // the west edge
    s.values[static_cast<std::size_t>(y) * s.width + 300] = 200.0f;  // the east edge
  }
  const fs::path p = scratch("sparse.tif");
  writeDem(p, s);
  const Dem dem = readDem(p.string());
  ASSERT_EQ(dem.terrain.width, 301);
  EXPECT_NEAR(dem.terrain.metresAt(150, 1), 100.0, 1.0 / 256);  // 150 cells from both edges
  EXPECT_GT(dem.terrain.metresAt(295, 1), 150.0);               // 5 cells from the east edge
  EXPECT_LT(dem.terrain.metresAt(5, 1), 150.0);
  EXPECT_TRUE(mentions(dem.notes, "nodata cells filled"));
}

TEST(DemReader, RealExcerptGeographicWithNodata) {
  const fs::path p = fs::path(VBIM_SOURCE_DIR) / "tests/lighting/data/luxembourg_elev.tif";
  const Dem dem = readDem(p.string());
  EXPECT_EQ(dem.terrain.width, 95);
  EXPECT_EQ(dem.terrain.height, 139);  // 90 rows of 926.9 m resampled to square cells of 599.7 m
  EXPECT_NEAR(dem.terrain.cellSize, 599.7, 0.1);
  const auto [lo, hi] = std::minmax_element(dem.terrain.heights.begin(), dem.terrain.heights.end());
  EXPECT_GT(*lo * dem.terrain.heightStep, 100.0);  // Luxembourg: about 140 m to 560 m
  EXPECT_LT(*hi * dem.terrain.heightStep, 600.0);
  EXPECT_TRUE(mentions(dem.notes, "nodata cells filled"));
}

std::string refusal(const fs::path& p) {
  try {
    readDem(p.string());
  } catch (const LightingError& e) {
    return e.what();
  }
  return "accepted";
}

// The header alone refuses a strip: an ASCII grid claiming 1,000,000 x 2 cells that holds three
// values is refused as a strip, not read (reading it would fail with "cannot read the heights").
TEST(DemReader, StripsAreRefusedFromTheHeaderBeforeAnyHeightIsRead) {
  const fs::path strip = scratch("strip.asc");
  std::ofstream(strip) << "ncols 1000000\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n";
  EXPECT_NE(refusal(strip).find("strip.asc: the DEM is 1000000 x 2 square cells, more than 256 times longer"),
            std::string::npos)
      << refusal(strip);
  DemSpec s;
  s.width = 257;
  s.height = 1;
  s.values = ramp(257, 1, 10.0, 1.0, 0.0);
  writeDem(scratch("257.tif"), s);
  EXPECT_NE(refusal(scratch("257.tif")).find("a strip, not a terrain"), std::string::npos);
  s.width = 256;
  s.values = ramp(256, 1, 10.0, 1.0, 0.0);
  writeDem(scratch("256.tif"), s);
  EXPECT_EQ(readDem(scratch("256.tif").string()).terrain.width, 256);  // at the limit
}

// Nearly all nodata is refused rather than filled into a flat terrain: at least 1 cell in 1,000
// must hold a height.
TEST(DemReader, AGridThatIsNearlyAllNodataIsRefused) {
  DemSpec s;
  s.width = 100;
  s.height = 100;
  s.hasNodata = true;
  s.values.assign(100 * 100, -9999.0f);
  for (int i = 0; i < 9; ++i) s.values[static_cast<std::size_t>(i * 1111)] = 50.0f + i;
  writeDem(scratch("sparse9.tif"), s);
  EXPECT_NE(refusal(scratch("sparse9.tif")).find("only 9 of the DEM's 10000 cells hold a height"), std::string::npos)
      << refusal(scratch("sparse9.tif"));
  s.values[5000] = 70.0f;  // 10 of 10,000: accepted, the rest filled
  writeDem(scratch("sparse10.tif"), s);
  EXPECT_EQ(readDem(scratch("sparse10.tif").string()).terrain.width, 100);
}

// A fuzz finding (tests/lighting/data/README.md): refused for its 1 x 6,444,444 m cells before
// anything is resampled, not read for seconds into a huge grid.
TEST(DemReader, FuzzFindingDamagedAsciiGridIsRefusedAtOnce) {
  const fs::path p = fs::path(VBIM_SOURCE_DIR) / "tests/lighting/data/fuzz_damaged_nrows.asc";
  try {
    readDem(p.string());
    FAIL() << "the damaged grid was accepted";
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("fuzz_damaged_nrows.asc: cells of 1 x 6.44444e+06 m"), std::string::npos)
        << e.what();
  }
}

TEST(TerrainFile, PicturesKeepTheirScalesAndFloatsAreMetres) {
  const fs::path png = scratch("hf16.png"), exr = scratch("hf.exr");
  testing::writeRaw(png, 2, 2, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>{0, 65535, 32768, 1});
  testing::writeRaw(exr, 2, 2, 1, OIIO::TypeDesc::FLOAT, std::vector<float>{0.0f, 812.5f, 3.25f, 100.0f});
  const TerrainFile a = loadTerrainFile(png.string(), {});
  EXPECT_FALSE(a.georeferenced);
  EXPECT_DOUBLE_EQ(a.terrain.cellSize, 10.0);
  EXPECT_NEAR(a.terrain.metresAt(1, 0), 1000.0, 1e-9);  // full scale 1000 m by default
  const TerrainFile b = loadTerrainFile(exr.string(), {});
  EXPECT_NEAR(b.terrain.metresAt(1, 0), 812.5, 1.0 / 256);  // metres as they are
  const TerrainFile c = loadTerrainFile(exr.string(), {.cellSize = 2.0, .verticalScale = 3.0});
  EXPECT_NEAR(c.terrain.metresAt(1, 0), 3 * 812.5, 1.0 / 256);
  EXPECT_DOUBLE_EQ(c.terrain.cellSize, 2.0);
}

TEST(GeoTiffLayers, WrittenWithTheDemsGeoreferencing) {
  DemSpec s;
  s.width = 5;
  s.height = 3;
  s.values = ramp(5, 3, 0.0, 1.0, 1.0);
  s.gt = {400000, 20, 0, 6000000, 0, -20};
  s.epsg = 32633;
  const fs::path dem = scratch("layer_dem.tif"), out = scratch("layer.tif");
  writeDem(dem, s);
  const TerrainFile f = loadTerrainFile(dem.string(), {});
  FloatImage rgb(5, 3, 3);
  for (std::size_t i = 0; i < rgb.pixels.size(); ++i) rgb.pixels[i] = static_cast<float>(i) * 0.25f;
  writeGeoTiff(out, rgb, f.geo, "test layer");
  EXPECT_FALSE(fs::exists(scratch("layer.tif.tmp")));
  const GeoTiffLayer back = readGeoTiff(out);
  EXPECT_EQ(back.geo.geoTransform, s.gt);
  OGRSpatialReference a, b;
  a.importFromEPSG(32633);
  b.importFromWkt(back.geo.srsWkt.c_str());
  EXPECT_TRUE(a.IsSame(&b)) << back.geo.srsWkt;
  EXPECT_EQ(back.image.channels, 3);
  EXPECT_EQ(back.image.pixels, rgb.pixels);
  EXPECT_EQ(back.description, "test layer");
}

}  // namespace
}  // namespace vbim::lighting
