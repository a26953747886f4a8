#include "lighting/dem_reader.hpp"

#include <gdal_alg.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "lighting/error.hpp"
#include "lighting/gdal_support.hpp"

namespace vbim::lighting {

namespace {

constexpr double kFoot = 0.3048;                 // international foot
constexpr double kUsSurveyFoot = 1200.0 / 3937;  // US survey foot

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void checkGridSize(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw LightingError(path + ": the DEM is empty (" + std::to_string(width) + "x" + std::to_string(height) + ")");
  }
  if (static_cast<std::int64_t>(width) * height > kMaxDemCells) {
    throw LightingError(path + ": the DEM is " + std::to_string(width) + "x" + std::to_string(height) +
                        " cells, more than the " + std::to_string(kMaxDemCells) + " vbim reads; crop it first");
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Metres per height unit named by a band's unit type; 0 when the name is not known.
double metresPerUnit(const std::string& unit) {
  const std::string u = lower(unit);
  if (u == "m" || u == "metre" || u == "meter" || u == "metres" || u == "meters") return 1.0;
  if (u == "ft" || u == "foot" || u == "feet" || u == "international foot") return kFoot;
  if (u == "us-ft" || u == "ftus" || u == "us survey foot" || u == "foot_us") return kUsSurveyFoot;
  return 0.0;
}

struct Grid {
  int width, height;
  std::vector<float> values;  // row-major
};

// How far (in cells) GDALFillNodata looks for valid cells; also GDAL's own default in
// gdal_fillnodata (https://gdal.org/programs/gdal_fillnodata.html). Its cost grows with this
// distance times the grid, so a search across the whole grid made a sparse XYZ file of a few
// points on a 1,000,000 x 4 grid run for minutes.
constexpr int kFillSearchCells = 100;

// Fills invalid cells (false in `valid`) with GDALFillNodata's inverse-distance interpolation in an
// in-memory copy, then any left with the lowest valid value. Returns how many were filled.
std::size_t fillNodata(Grid& g, const std::vector<bool>& valid, const std::string& path) {
  const std::size_t bad = static_cast<std::size_t>(std::count(valid.begin(), valid.end(), false));
  if (bad == 0) return 0;
  if (bad == valid.size()) throw LightingError(path + ": every cell is nodata; expected at least one height");
  if (const std::size_t good = valid.size() - bad; good * static_cast<std::size_t>(kMinValidOneIn) < valid.size()) {
    throw LightingError(path + ": only " + std::to_string(good) + " of the DEM's " + std::to_string(valid.size()) +
                        " cells hold a height (fewer than 1 in " + std::to_string(kMinValidOneIn) +
                        "); the rest is nodata: crop it to where it has heights");
  }
  float lowest = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < valid.size(); ++i)
    if (valid[i]) lowest = std::min(lowest, g.values[i]);
  constexpr float kHole = -3.0e38f;
  for (std::size_t i = 0; i < valid.size(); ++i)
    if (!valid[i]) g.values[i] = kHole;

  const gdal::QuietErrors quiet;
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  gdal::Dataset ds(mem != nullptr ? mem->Create("", g.width, g.height, 1, GDT_Float32, nullptr) : nullptr);
  if (!ds) throw LightingError(path + ": " + gdal::lastError("cannot make an in-memory copy to fill nodata"));
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetNoDataValue(kHole);
  if (band->RasterIO(GF_Write, 0, 0, g.width, g.height, g.values.data(), g.width, g.height, GDT_Float32, 0, 0,
                     nullptr) != CE_None ||
      GDALFillNodata(GDALRasterBand::ToHandle(band), nullptr, kFillSearchCells, 0, 0, nullptr, nullptr, nullptr) !=
          CE_None ||
      band->RasterIO(GF_Read, 0, 0, g.width, g.height, g.values.data(), g.width, g.height, GDT_Float32, 0, 0,
                     nullptr) != CE_None) {
    throw LightingError(path + ": " + gdal::lastError("filling the nodata cells failed"));
  }
  for (float& v : g.values)
    if (v == kHole) v = lowest;
  return bad;
}

// Bilinear resampling to w x h over the same extent (pixel centres at (i + 0.5) / w of the extent).
Grid resample(const Grid& g, int w, int h) {
  Grid out{w, h, std::vector<float>(static_cast<std::size_t>(w) * h)};
  for (int y = 0; y < h; ++y) {
    const double sy = std::clamp((y + 0.5) * g.height / h - 0.5, 0.0, g.height - 1.0);
    const int y0 = std::min(static_cast<int>(sy), g.height - 1), y1 = std::min(y0 + 1, g.height - 1);
    const double fy = sy - y0;
    for (int x = 0; x < w; ++x) {
      const double sx = std::clamp((x + 0.5) * g.width / w - 0.5, 0.0, g.width - 1.0);
      const int x0 = std::min(static_cast<int>(sx), g.width - 1), x1 = std::min(x0 + 1, g.width - 1);
      const double fx = sx - x0;
      auto at = [&](int xx, int yy) {
        return static_cast<double>(g.values[static_cast<std::size_t>(yy) * g.width + xx]);
      };
      const double top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
      const double bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
      out.values[static_cast<std::size_t>(y) * w + x] = static_cast<float>(top + (bottom - top) * fy);
    }
  }
  return out;
}

void flipRows(Grid& g) {
  for (int y = 0; y < g.height / 2; ++y) {
    auto a = g.values.begin() + static_cast<std::ptrdiff_t>(y) * g.width;
    auto b = g.values.begin() + static_cast<std::ptrdiff_t>(g.height - 1 - y) * g.width;
    std::swap_ranges(a, a + g.width, b);
  }
}

void flipColumns(Grid& g) {
  for (int y = 0; y < g.height; ++y) {
    auto a = g.values.begin() + static_cast<std::ptrdiff_t>(y) * g.width;
    std::reverse(a, a + g.width);
  }
}

}  // namespace

MetresPerDegree metresPerDegree(double latDeg, double a, double invF) {
  const double f = invF > 0 ? 1.0 / invF : 0.0, e2 = f * (2 - f);
  const double phi = latDeg * std::numbers::pi / 180, s = std::sin(phi);
  const double w = std::sqrt(1 - e2 * s * s);
  const double meridional = a * (1 - e2) / (w * w * w), primeVertical = a / w;
  return {meridional * std::numbers::pi / 180, primeVertical * std::cos(phi) * std::numbers::pi / 180};
}

bool isGeoreferencedRaster(const std::string& path) {
  const gdal::Dataset ds = gdal::openRaster(path);
  double gt[6];
  return ds && ds->GetRasterCount() >= 1 && ds->GetGeoTransform(gt) == CE_None;
}

// The grid of square cells a DEM is resampled to (cells dx x dy metres), refused when it would be
// too large or the cells degenerate. Needs only the header: checked before the heights are read.
struct SquareCells {
  bool resample = false;
  double cell = 0;
  int width = 0, height = 0;
};

void checkGridAspect(const std::string& path, std::int64_t w, std::int64_t h) {
  if (std::max(w, h) > kMaxGridAspect * std::min(w, h)) {
    throw LightingError(path + ": the DEM is " + std::to_string(w) + " x " + std::to_string(h) +
                        " square cells, more than " + std::to_string(kMaxGridAspect) +
                        " times longer one way than the other: a strip, not a terrain; crop it");
  }
}

SquareCells squareCells(const std::string& path, const Grid& g, double dx, double dy) {
  SquareCells sq{false, dx, g.width, g.height};
  if (!(std::fabs(dx - dy) > 1e-9 * std::max(dx, dy))) {
    checkGridAspect(path, g.width, g.height);
    return sq;
  }
  sq.resample = true;
  sq.cell = std::min(dx, dy);
  const double wide = std::max(1.0, std::round(g.width * dx / sq.cell));
  const double high = std::max(1.0, std::round(g.height * dy / sq.cell));
  if (!(wide * high <= static_cast<double>(kMaxDemCells))) {
    throw LightingError(path + ": square cells of " + number(sq.cell) + " m would need " + number(wide) + " x " +
                        number(high) + " cells, more than the " + std::to_string(kMaxDemCells) +
                        " vbim reads; crop the DEM or give --cell-size");
  }
  // Square cells multiply the grid by the cells' aspect ratio. A geographic grid has it at
  // 1 / cos(latitude): 16 is 86.4 degrees. Beyond that the cells are degenerate (a 3-cell ASCII
  // grid with dy = 6,444,444 x dx asked for 19 million cells and gigabytes).
  if (std::max(dx, dy) > kMaxCellAspect * sq.cell) {
    throw LightingError(path + ": cells of " + number(dx) + " x " + number(dy) + " m are more than " +
                        number(kMaxCellAspect) + " times longer one way than the other; vbim resamples to " +
                        "square cells: warp the DEM to square cells first (e.g. gdalwarp -tr)");
  }
  sq.width = static_cast<int>(wide);
  sq.height = static_cast<int>(high);
  checkGridAspect(path, sq.width, sq.height);
  return sq;
}

Dem readDem(const std::string& path, const DemOverrides& overrides) {
  std::string why;
  const gdal::Dataset ds = gdal::openRaster(path, &why);
  if (!ds) throw LightingError(path + ": cannot read the DEM: " + why);
  if (ds->GetRasterCount() != 1) {
    throw LightingError(path + ": the DEM has " + std::to_string(ds->GetRasterCount()) +
                        " bands; expected one band of heights");
  }
  Dem dem;
  auto& gt = dem.geo.geoTransform;
  if (ds->GetGeoTransform(gt.data()) != CE_None) {
    throw LightingError(path + ": the DEM has no geotransform; expected a georeferenced raster");
  }
  if (gt[2] != 0 || gt[4] != 0) {
    throw LightingError(path + ": the DEM's grid is rotated or sheared (geotransform terms " + number(gt[2]) + ", " +
                        number(gt[4]) + "); expected a north-up grid (warp it first, e.g. gdalwarp)");
  }
  for (const double term : gt) {
    if (!std::isfinite(term)) throw LightingError(path + ": the DEM's geotransform has a term that is not a number");
  }
  if (gt[1] == 0 || gt[5] == 0) throw LightingError(path + ": the DEM's geotransform has a zero pixel size");

  Grid g{ds->GetRasterXSize(), ds->GetRasterYSize(), {}};
  checkGridSize(path, g.width, g.height);
  dem.fileWidth = g.width;
  dem.fileHeight = g.height;
  bool flippedRows = false, flippedColumns = false;
  GDALRasterBand* band = ds->GetRasterBand(1);

  // Horizontal units.
  const OGRSpatialReference* srs = ds->GetSpatialRef();
  double dx = std::fabs(gt[1]), dy = std::fabs(gt[5]);
  const double centreY = gt[3] + gt[5] * g.height / 2;
  double verticalUnit = 1.0;
  std::string verticalFrom = "taken as metres (the file names no unit)";
  if (srs == nullptr) {
    dem.notes.push_back("no spatial reference: grid units taken as metres");
  } else if (srs->IsGeographic()) {
    const double degrees = srs->GetAngularUnits() * 180 / std::numbers::pi;  // degrees per angular unit
    const double lat = centreY * degrees;
    if (!(std::fabs(lat) <= 90)) {
      throw LightingError(path + ": the DEM's centre latitude " + number(lat) + " is outside -90..90 degrees");
    }
    OGRErr err = OGRERR_NONE;
    const double a = srs->GetSemiMajor(&err), invF = srs->GetInvFlattening(&err);
    const MetresPerDegree m = metresPerDegree(lat, a, invF);
    dx *= degrees * m.lon;
    dy *= degrees * m.lat;
    dem.notes.push_back("geographic coordinates: " + number(m.lat) + " m per degree of latitude and " + number(m.lon) +
                        " m per degree of longitude at latitude " + number(lat));
  } else {
    const double metres = srs->GetLinearUnits();
    dx *= metres;
    dy *= metres;
    if (metres != 1.0) {
      verticalUnit = metres;
      verticalFrom = "converted to metres from the spatial reference's linear unit (" + number(metres) + " m)";
    }
  }
  if (const std::string unit = band->GetUnitType(); !unit.empty()) {
    verticalUnit = metresPerUnit(unit);
    if (verticalUnit == 0) {
      throw LightingError(path + ": the height unit '" + unit + "' is not known; expected m, ft or US survey ft");
    }
    verticalFrom = "converted to metres from the band's unit '" + unit + "'";
  }
  int hasScale = 0, hasOffset = 0;
  const double scale = band->GetScale(&hasScale), offset = band->GetOffset(&hasOffset);

  // Everything the header alone can refuse is refused before the heights are read: a 4-line XYZ
  // file made GDAL a 106,024,024 x 2 grid that took 74 s and 6 GB to read and then to refuse.
  const SquareCells square = squareCells(path, g, dx, dy);
  g.values.resize(static_cast<std::size_t>(g.width) * g.height);
  {
    const gdal::QuietErrors quiet;
    if (band->RasterIO(GF_Read, 0, 0, g.width, g.height, g.values.data(), g.width, g.height, GDT_Float32, 0, 0,
                       nullptr) != CE_None) {
      throw LightingError(path + ": " + gdal::lastError("cannot read the heights"));
    }
  }

  // Validity before any arithmetic: the nodata value is compared with the stored value.
  int hasNodata = 0;
  const double nodata = band->GetNoDataValue(&hasNodata);
  const float nodataF = static_cast<float>(nodata);
  std::vector<bool> valid(g.values.size());
  for (std::size_t i = 0; i < g.values.size(); ++i) {
    const float v = g.values[i];
    valid[i] = std::isfinite(v) && !(hasNodata != 0 && v == nodataF);
  }
  for (std::size_t i = 0; i < g.values.size(); ++i) {
    if (valid[i]) g.values[i] = static_cast<float>((g.values[i] * scale + offset) * verticalUnit);
  }
  if (const std::size_t filled = fillNodata(g, valid, path); filled > 0) {
    dem.notes.push_back(std::to_string(filled) +
                        " nodata cells filled by inverse-distance interpolation from the nearest valid cells");
  }
  dem.notes.push_back("heights " + verticalFrom);

  if (gt[5] > 0) {
    flipRows(g);
    gt[3] += gt[5] * g.height;
    gt[5] = -gt[5];
    flippedRows = true;
    dem.notes.push_back("south-up grid flipped to north-up");
  }
  if (gt[1] < 0) {
    flipColumns(g);
    gt[0] += gt[1] * g.width;
    gt[1] = -gt[1];
    flippedColumns = true;
    dem.notes.push_back("east-to-west grid flipped to west-to-east");
  }
  double cell = square.cell;
  if (square.resample) {
    const int w = square.width;
    const int h = square.height;
    gt[1] *= static_cast<double>(g.width) / w;
    gt[5] *= static_cast<double>(g.height) / h;
    dem.notes.push_back("cells of " + number(dx) + " x " + number(dy) + " m resampled bilinearly from " +
                        std::to_string(g.width) + "x" + std::to_string(g.height) + " to " + std::to_string(w) + "x" +
                        std::to_string(h) + " square cells of " + number(cell) + " m");
    g = resample(g, w, h);
  }
  {
    // Texel x of the (resampled) grid sits at x' = (x + 0.5) W / w - 0.5 of the flipped file grid
    // (resample() above), and at W - 1 - x' of the file when the columns were flipped; rows alike.
    const double sx = static_cast<double>(dem.fileWidth) / g.width, sy = static_cast<double>(dem.fileHeight) / g.height;
    GridMapping& m = dem.toFile;
    m = {0.5 * sx - 0.5, sx, 0.5 * sy - 0.5, sy};
    if (flippedColumns) m = {dem.fileWidth - 1 - m.x0, -m.dx, m.y0, m.dy};
    if (flippedRows) m = {m.x0, m.dx, dem.fileHeight - 1 - m.y0, -m.dy};
  }
  if (overrides.verticalScale) {
    if (!(*overrides.verticalScale > 0) || !std::isfinite(*overrides.verticalScale)) {
      throw LightingError(path + ": --vertical-scale must be a positive number");
    }
    for (float& v : g.values) v = static_cast<float>(v * *overrides.verticalScale);
    dem.notes.push_back("heights multiplied by " + number(*overrides.verticalScale) + " (--vertical-scale)");
  }
  if (overrides.cellSize) {
    dem.notes.push_back("cell size " + number(*overrides.cellSize) + " m (--cell-size) instead of the file's " +
                        number(cell) + " m");
    cell = *overrides.cellSize;
  } else {
    dem.notes.push_back("cell size " + number(cell) + " m from the file");
  }
  if (srs != nullptr) {
    char* wkt = nullptr;
    if (srs->exportToWkt(&wkt) == OGRERR_NONE && wkt != nullptr) dem.geo.srsWkt = wkt;
    CPLFree(wkt);
  }
  dem.terrain = terrainFromMetres(g.width, g.height, g.values, cell, path);
  return dem;
}

}  // namespace vbim::lighting
