// Item 1 (heightfields from files) and item 4 (vbim lightmap), with the bad-input cases of the
// issue: not single-channel, empty, NaN heights, latitude outside +-90, zero frames, colour map of
// another size. Each must give a clear message and a non-zero exit.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lighting/errors.hpp"
#include "lighting/image_io.hpp"

namespace vbim::lighting {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir() {
  return fs::temp_directory_path() / ("vbim_lighting_test_" + std::to_string(::getpid()));
}

fs::path scratch(const std::string& name) {
  fs::create_directories(scratchDir());
  return scratchDir() / name;
}

class RemoveScratch : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(scratchDir(), ec);
  }
};
const auto* const kRemoveScratch = ::testing::AddGlobalTestEnvironment(new RemoveScratch);

template <typename T>
void writeRaw(const fs::path& path, int w, int h, int channels, OIIO::TypeDesc type, const std::vector<T>& data) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(w, h, channels, type)));
  ASSERT_TRUE(out->write_image(type, data.data()));
  ASSERT_TRUE(out->close());
}

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

TEST(ImageIo, SixteenBitPngHeightsAreKeptExactly) {
  std::vector<std::uint16_t> v(6 * 4);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint16_t>(i * 2500);
  const fs::path p = scratch("hf16.png");
  writeRaw(p, 6, 4, 1, OIIO::TypeDesc::UINT16, v);
  const Terrain t = readHeightfield(p.string(), 5.0, 655.35);
  ASSERT_EQ(t.width, 6);
  ASSERT_EQ(t.height, 4);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(t.heights[i], v[i]);
  EXPECT_DOUBLE_EQ(t.heightStep, 0.01);
  EXPECT_DOUBLE_EQ(t.cellSize, 5.0);
}

TEST(ImageIo, FloatExrHeightsAreMetresTimesScale) {
  std::vector<float> v = {0.0f, 1.5f, 100.25f, -3.0f};
  const fs::path p = scratch("hf.exr");
  writeRaw(p, 2, 2, 1, OIIO::TypeDesc::FLOAT, v);
  const Terrain t = readHeightfield(p.string(), 10.0, 2.0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(t.heights[i] * t.heightStep, v[i] * 2.0, 1.0 / 512);
}

TEST(ImageIo, RejectsRgbHeightfieldsAndNaN) {
  const fs::path rgb = scratch("rgb.png");
  writeRaw(rgb, 4, 4, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(48, 7));
  try {
    readHeightfield(rgb.string(), 10, 100);
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("rgb.png: the heightfield has 3 channels; expected a single-channel"),
              std::string::npos)
        << e.what();
  }
  const fs::path nan = scratch("nan.exr");
  std::vector<float> v(9, 1.0f);
  v[5] = std::nanf("");
  writeRaw(nan, 3, 3, 1, OIIO::TypeDesc::FLOAT, v);
  try {
    readHeightfield(nan.string(), 10, 1);
    FAIL();
  } catch (const LightingError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.exr: height at pixel (2, 1) is NaN"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readHeightfield(scratch("missing.png").string(), 10, 1), LightingError);
  std::ofstream(scratch("garbage.png")) << "not an image";
  EXPECT_THROW(readHeightfield(scratch("garbage.png").string(), 10, 1), LightingError);
}

TEST(ImageIo, WritesExrAndPngRoundTrip) {
  FloatImage img(3, 2, 3);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = static_cast<float>(i) / 17.0f;
  writeImage(scratch("out.exr").string(), img);
  writeImage(scratch("out.png").string(), img);
  auto in = OIIO::ImageInput::open(scratch("out.exr").string());
  ASSERT_TRUE(in);
  std::vector<float> back(img.pixels.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()));
  EXPECT_EQ(back, img.pixels);
  auto png = OIIO::ImageInput::open(scratch("out.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_FALSE(fs::exists(scratch(".out.tmp.png")));
}

TEST(LightmapCli, WritesFramesAndDebugLayers) {
  const fs::path out = scratch("cli_ok");
  fs::remove_all(out);
  const Result r =
      runVbim("lightmap --size 32 --frames 3 --sky-width 16 --debug all --format both --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"lightmap_0000.png", "lightmap_0002.exr", "sky_0001.png", "shadow_0002.png", "horizon_NE.png",
                        "horizon_S_deg.exr", "sky_factor_K.exr", "frames.csv"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_FALSE(fs::exists(out / "lightmap_0003.png"));
  // A second run into the same, non-empty directory is refused unless --force.
  EXPECT_NE(runVbim("lightmap --size 32 --frames 1 --out " + out.string()).code, 0);
  EXPECT_EQ(runVbim("lightmap --size 32 --frames 1 --force --out " + out.string()).code, 0);
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
  const fs::path toml = scratch("bad.toml");
  std::ofstream(toml) << "[lighting]\nlatitude_deg = 200\n";
  expectFailure("lightmap --size 16 --config " + toml.string(), "latitude_deg", out);
}

}  // namespace
}  // namespace vbim::lighting
