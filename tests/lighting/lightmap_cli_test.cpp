// vbim lightmap run as a child process, with the bad-input cases: a heightfield that is not
// single-channel, empty or holds NaN heights, latitude outside +-90, zero frames, a colour map of
// another size. Each must give a clear message and a non-zero exit. (Reading and writing the files
// themselves is tested in tests/lighting/image_files_test.cpp.)
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/lighting/gdal_dems.hpp"
#include "tests/lighting/oiio_scratch.hpp"

namespace vbim::lighting {
namespace {

namespace fs = std::filesystem;

using testing::RemoveScratch;
using testing::scratch;
using testing::scratchDir;
using testing::writeRaw;
const auto* const kRemoveScratch = ::testing::AddGlobalTestEnvironment(new RemoveScratch);

struct Result {
  int code;
  std::string err;
};

Result runVbim(const std::string& args) {
  const fs::path errFile = scratch("stderr.txt");
  const std::string cmd = std::string(VBIM_BINARY) + " " + args + " >/dev/null 2>" + errFile.string();
  const int status = std::system(cmd.c_str());
  std::ifstream in(errFile);
  std::stringstream s;
  s << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, s.str()};
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A DEM in metres needs no option: its cell size and heights are the file's, and the debug layers
// come back as GeoTIFF with its geotransform and SRS (read here with GDAL itself).
TEST(LightmapCli, DemWithNoOptionsAndGeoTiffLayers) {
  testing::DemSpec s;
  s.width = 48;
  s.height = 40;
  s.values.resize(48 * 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x) s.values[static_cast<std::size_t>(y) * 48 + x] = 800.0f + 0.5f * x + 0.25f * y;
  s.gt = {350000, 25, 0, 5100000, 0, -25};
  s.epsg = 32631;
  const fs::path dem = scratch("cli_dem.tif"), out = scratch("cli_dem_out"), log = scratch("cli_dem_stdout.txt");
  testing::writeDem(dem, s);
  fs::remove_all(out);
  const std::string cmd = std::string(VBIM_BINARY) + " lightmap --terrain " + dem.string() +
                          " --frames 1 --sky-width 16 --sun-azimuth 135 --sun-elevation 30 --debug all "
                          "--layers-format tif --format tif --shadow-rays --out " +
                          out.string() + " >" + log.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << readText(log);
  EXPECT_NE(readText(log).find("cell size 25 m from the file"), std::string::npos) << readText(log);
  EXPECT_NE(readText(out / "frames.csv").find("0,6,30,135,sun"), std::string::npos) << readText(out / "frames.csv");

  OGRSpatialReference utm;
  utm.importFromEPSG(32631);
  for (const char* f :
       {"sky_factor_K.tif", "horizon_SE_deg.tif", "shadow_0000.tif", "nl_0000.tif", "lightmap_0000.tif"}) {
    GDALDataset* ds = GDALDataset::Open((out / f).string().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
    ASSERT_NE(ds, nullptr) << f;
    std::array<double, 6> gt{};
    ds->GetGeoTransform(gt.data());
    EXPECT_EQ(gt, s.gt) << f;
    ASSERT_NE(ds->GetSpatialRef(), nullptr) << f;
    EXPECT_TRUE(ds->GetSpatialRef()->IsSame(&utm)) << f;
    EXPECT_EQ(ds->GetRasterXSize(), 48) << f;
    std::vector<float> v(48 * 40);
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 48, 40, v.data(), 48, 40, GDT_Float32, 0, 0, nullptr),
              CE_None);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    if (std::string(f) == "sky_factor_K.tif") {
      // A gentle slope in metres sees nearly all the sky (a 1000x taller terrain would not).
      EXPECT_GT(*lo, 0.95f);
      EXPECT_LE(*hi, 1.0f);
    }
    if (std::string(f) == "nl_0000.tif") {
      // Slope 0.02 up to the east, 0.01 up to the south, sun at 30 deg from the SE: N.L near sin 30.
      EXPECT_NEAR(*lo, 0.5f, 0.02f);
      EXPECT_NEAR(*hi, 0.5f, 0.02f);
    }
    GDALClose(ds);
  }
}

TEST(LightmapCli, WritesFramesAndDebugLayers) {
  const fs::path out = scratch("cli_ok");
  fs::remove_all(out);
  const Result r =
      runVbim("lightmap --size 32 --frames 3 --sky-width 16 --debug all --format both --sky-directions 16 --out " +
              out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"lightmap_0000.png", "lightmap_0002.exr", "sky_0001.png", "shadow_0002.png", "horizon_NE.png",
                        "horizon_S_deg.exr", "sky_factor_K.exr", "nl_0001.exr", "frames.csv"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_FALSE(fs::exists(out / "lightmap_0003.png"));
  // A second run into the same, non-empty directory is refused unless --force.
  EXPECT_NE(runVbim("lightmap --size 32 --frames 1 --out " + out.string()).code, 0);
  EXPECT_EQ(runVbim("lightmap --size 32 --frames 1 --force --out " + out.string()).code, 0);
}

// Mean of the 8-bit channels of an image file (OpenImageIO).
double meanLevel(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return -1;
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<unsigned char> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data())) return -1;
  double sum = 0;
  for (unsigned char v : px) sum += v;
  return sum / static_cast<double>(px.size());
}

// The first picture a user opens is lit: `vbim lightmap --frames 1` renders the day's start hour,
// which by default is in daylight (6 h at 45 N on 21 June), far brighter than the night (issue #33).
TEST(LightmapCli, TheDefaultFirstFrameIsInDaylight) {
  const fs::path day = scratch("cli_daylight"), night = scratch("cli_night");
  fs::remove_all(day);
  fs::remove_all(night);
  const Result d = runVbim("lightmap --size 32 --frames 1 --sky-width 16 --out " + day.string());
  ASSERT_EQ(d.code, 0) << d.err;
  const Result n = runVbim("lightmap --size 32 --frames 1 --sky-width 16 --start-hour 0 --out " + night.string());
  ASSERT_EQ(n.code, 0) << n.err;
  const double dayLevel = meanLevel(day / "lightmap_0000.png"), nightLevel = meanLevel(night / "lightmap_0000.png");
  // Here: 33 at 6 h; 4.4 at the old default of 4 h (moonlight), 2.9 at midnight.
  EXPECT_GT(dayLevel, 20.0) << "frame 0 of the defaults: " << readText(day / "frames.csv");
  EXPECT_GT(dayLevel, 4.0 * nightLevel) << "day " << dayLevel << ", night " << nightLevel;
  EXPECT_NE(readText(day / "frames.csv").find("\n0,6,"), std::string::npos) << readText(day / "frames.csv");
}

void expectFailure(const std::string& args, const std::string& message, const fs::path& out) {
  fs::remove_all(out);
  const Result r = runVbim(args + " --out " + out.string());
  EXPECT_NE(r.code, 0) << args;
  EXPECT_NE(r.err.find(message), std::string::npos) << args << "\nstderr: " << r.err;
  EXPECT_FALSE(fs::exists(out)) << "output directory left behind by: " << args;
}

TEST(LightmapCli, BadInputGivesAClearMessageAndNonZeroExit) {
  const fs::path out = scratch("cli_bad");
  const fs::path rgb = scratch("cli_rgb.png"), nan = scratch("cli_nan.exr"), hf = scratch("cli_hf.png"),
                 colour = scratch("cli_colour.png"), empty = scratch("cli_empty.png");
  writeRaw(rgb, 4, 4, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(48, 7));
  std::vector<float> v(16, 1.0f);
  v[6] = std::nanf("");
  writeRaw(nan, 4, 4, 1, OIIO::TypeDesc::FLOAT, v);
  writeRaw(hf, 8, 8, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>(64, 1000));
  writeRaw(colour, 8, 6, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(144, 100));
  std::ofstream(empty) << "";
  expectFailure("lightmap --terrain " + rgb.string(), "has 3 channels; expected a single-channel", out);
  expectFailure("lightmap --terrain " + nan.string(), "height at pixel (2, 1) is NaN", out);
  expectFailure("lightmap --terrain " + empty.string(), "cli_empty.png: cannot read the heightfield", out);
  expectFailure("lightmap --size 16 --latitude 91", "lighting.latitude_deg = 91 is outside [-90, 90]", out);
  expectFailure("lightmap --size 16 --latitude -100", "lighting.latitude_deg = -100 is outside [-90, 90]", out);
  expectFailure("lightmap --size 16 --frames 0", "lighting.frames = 0 is outside", out);
  expectFailure("lightmap --terrain " + hf.string() + " --albedo " + colour.string(),
                "colour map is 8x6, expected the heightfield's size 8x8", out);
  expectFailure("lightmap --size 16 --debug nonsense", "unknown layer 'nonsense'", out);
  expectFailure("lightmap --size 16 --sky-directions 12", "lighting.sky_directions = 12 must be 8, 16 or 32", out);
  expectFailure("lightmap --size 16 --sun-elevation 95", "lighting.sun_elevation_deg = 95 is outside [-90, 90]", out);
  expectFailure("lightmap --size 16 --layers-format png", "--layers-format 'png': expected exr or tif", out);
  expectFailure("lightmap --terrain " + hf.string() + " --bounce-albedo " + colour.string(),
                "cli_colour.png: colour map is", out);
  const fs::path toml = scratch("bad.toml");
  std::ofstream(toml) << "[lighting]\nlatitude_deg = 200\n";
  expectFailure("lightmap --size 16 --config " + toml.string(), "latitude_deg", out);
}

}  // namespace
}  // namespace vbim::lighting
