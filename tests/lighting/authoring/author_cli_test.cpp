// `vbim author --terrain/--procedural` as a user runs it: a stream our reader, ffprobe and ffmpeg
// accept, with the frame count and sizes asked for, whose decoded pictures match the generator's own
// frames; and the bad inputs (heightfield problems, latitude, zero frames...): a message naming the
// problem, a non-zero exit, and nothing under the output name (an old file there is left as it was).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/run_command.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "lighting/authoring/technique_a_stream.hpp"
#include "streams/authoring/mpeg2_decoder.hpp"
#include "streams/authoring/mpeg2_encoder.hpp"
#include "streams/demuxer.hpp"
#include "streams/format.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::lighting {
namespace {

namespace fs = std::filesystem;

// The codec at the default quantiser (q = 3): the streams tests measure 40 dB per plane on smooth
// frames; Technique A's texel-scale detail measured 36-39 dB on Y (tests/lighting/authoring/technique_a_stream_test).
constexpr double kCodecPsnrDb = 35.0;

struct Outcome {
  int status = -1;
  std::string out;  // stdout and stderr together
};

Outcome run(const std::string& args) {
  const vbim::testing::CommandResult r = vbim::testing::runCommand(std::string(VBIM_BINARY) + " " + args);
  return {r.status, r.output};
}

Outcome runTool(const std::string& cmd) {
  const vbim::testing::CommandResult r = vbim::testing::runCommand(cmd);
  return {r.status, r.output};
}

fs::path dir() {
  static const fs::path d = [] {
    const fs::path p = fs::temp_directory_path() / ("vbim_author_cli_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
  }();
  return d;
}

class RemoveDir : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir(), ec);
  }
};
const auto* const kRemoveDir = ::testing::AddGlobalTestEnvironment(new RemoveDir);

template <typename T>
void writeImage(const fs::path& path, int w, int h, int channels, OIIO::TypeDesc type, const std::vector<T>& data) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(w, h, channels, type)));
  ASSERT_TRUE(out->write_image(type, data.data()));
  ASSERT_TRUE(out->close());
}

// A 16-bit heightfield: a ridge running north-south, so the morning and evening sides differ.
void writeRidge(const fs::path& path, int w, int h) {
  std::vector<std::uint16_t> px(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = std::abs(x - w / 2.0) / (w / 2.0);
      px[static_cast<std::size_t>(y) * w + x] =
          static_cast<std::uint16_t>(60000 * std::max(0.0, 1 - d) * (0.8 + 0.2 * y / h));
    }
  writeImage(path, w, h, 1, OIIO::TypeDesc::UINT16, px);
}

// Nothing but the inputs in the directory: no output, no temporary left behind.
std::vector<std::string> streamFiles() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir())) {
    const std::string n = e.path().filename().string();
    if (n.find(".vbim") != std::string::npos) names.push_back(n);
  }
  return names;
}

TEST(AuthorCli, TerrainFileToAStreamThatMatchesTheGenerator) {
  const fs::path hf = dir() / "ridge.png", out = dir() / "ridge.vbim";
  writeRidge(hf, 80, 48);
  const std::string args = "author --terrain " + hf.string() +
                           " --cell-size 30 --vertical-scale 600 --latitude 30 --day 80 --start-hour 6 --end-hour 18 "
                           "--frame-count 7 --sky-width 64 --sky-patches 3 --sun-diameter 3 --fps 2 --loop 1 --out " +
                           out.string();
  const Outcome r = run(args);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("1 variant(s) x 7 frames, lightmap 80x48, sky 64x32"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << "no progress bar when stderr is not a terminal";

  // Our reader.
  const streams::StreamScan scan = streams::scanStreamFile(out);
  EXPECT_TRUE(scan.every2048);
  ASSERT_TRUE(scan.errors.empty()) << scan.errors.front().describe();
  ASSERT_TRUE(scan.descriptor);
  const streams::Descriptor& d = *scan.descriptor;
  EXPECT_EQ(d.framesPerVariant, 7u);
  ASSERT_EQ(d.variants.size(), 1u);
  EXPECT_EQ(d.variants[0].name, "clear");
  EXPECT_EQ(d.loopFrame, 1u);
  ASSERT_EQ(d.streams.size(), 2u);
  EXPECT_EQ(d.streams[0].width, 80);
  EXPECT_EQ(d.streams[0].height, 48);
  EXPECT_EQ(d.streams[1].width, 64);
  EXPECT_EQ(d.streams[1].height, 32);
  EXPECT_EQ(scan.pictures.size(), 14u);

  // ffprobe: two MPEG-2 video streams of 7 intra pictures each; ffmpeg decodes the whole file.
  const Outcome probe =
      runTool("ffprobe -v error -show_entries frame=pict_type,stream_index,width,height -of json " + out.string());
  ASSERT_EQ(probe.status, 0) << probe.out;
  int intra[2] = {0, 0};
  const nlohmann::json probed = nlohmann::json::parse(probe.out);
  for (const auto& f : probed.at("frames")) {
    EXPECT_EQ(f["pict_type"], "I");
    const int s = f["stream_index"].get<int>();
    ASSERT_TRUE(s == 0 || s == 1);
    ++intra[s];
    EXPECT_EQ(f["width"], s == 0 ? 80 : 64);
    EXPECT_EQ(f["height"], s == 0 ? 48 : 32);
  }
  EXPECT_EQ(intra[0], 7);
  EXPECT_EQ(intra[1], 7);
  const Outcome decode = runTool("ffmpeg -v error -nostdin -i " + out.string() + " -map 0 -f null -");
  EXPECT_EQ(decode.status, 0) << decode.out;

  // A decoded frame against the generator's own rendering of it (same settings), within the codec.
  TechniqueAStreamSettings s;
  s.terrain.heightfield = hf.string();
  s.terrain.cellSize = 30;
  s.terrain.verticalScale = 600;
  DayCycleParams p;
  p.latitudeDeg = 30;
  p.dayOfYear = 80;
  p.startHour = 6;
  p.endHour = 18;
  p.frames = 7;
  p.skyWidth = 64;
  p.skyPatches = 3;
  p.sunDiameterDeg = 3;
  DayCycleGenerator gen(loadTerrain(s.terrain), p);
  std::vector<Rgba8Image> wantLm, wantSky;
  for (int f = 0; f < gen.frameCount(); ++f) {
    FloatImage lm, sky;
    gen.renderFrame(f, lm, sky);
    wantLm.push_back(streamFrame(lm, s.tone));
    wantSky.push_back(streamFrame(sky, s.tone));
  }
  std::ifstream in(out, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The pictures as our reader reassembles them, decoded by libavcodec: each within the codec's PSNR
  // of its own frame, and closer to it than to any other frame.
  streams::Mpeg2Decoder dec;
  streams::Demuxer dm;
  for (std::uint32_t lsn = 0; lsn * streams::kSectorBytes < bytes.size(); ++lsn)
    dm.feed(std::span(bytes).subspan(std::size_t{lsn} * streams::kSectorBytes, streams::kSectorBytes), lsn);
  dm.finish();
  int compared = 0;
  for (const streams::Picture& pic : dm.pictures()) {
    ASSERT_TRUE(pic.frame);
    const bool isSky = pic.streamId == streams::kSkyStream;
    const std::vector<Rgba8Image>& want = isSky ? wantSky : wantLm;
    const Yuv420Image got = dec.decodeYuv(pic.data);
    const streams::PlanePsnr psnr = streams::psnrYuv(got, streams::rgbaToYuv420(want.at(*pic.frame)));
    EXPECT_GE(psnr.min(), kCodecPsnrDb) << (isSky ? "sky" : "lightmap") << " frame " << *pic.frame << ": Y " << psnr.y
                                        << " Cb " << psnr.cb << " Cr " << psnr.cr;
    for (std::size_t j = 0; j < want.size(); ++j) {
      if (j == *pic.frame || want[j].pixels == want[*pic.frame].pixels) continue;
      EXPECT_LT(streams::psnrYuv(got, streams::rgbaToYuv420(want[j])).min(), psnr.min())
          << (isSky ? "sky" : "lightmap") << " frame " << *pic.frame << " looks more like frame " << j;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 14);
  fs::remove(out);
}

TEST(AuthorCli, ProceduralWithTwoWeathersAndAConfigFile) {
  const fs::path cfg = dir() / "lighting.toml", out = dir() / "weather.vbim";
  std::ofstream(cfg) << "[lighting]\nlatitude_deg = 50\nsky_width = 32\nframes = 3\n";
  const Outcome r = run("author --procedural --size 32 --lighting-config " + cfg.string() +
                        " --frame-count 4 --weather clear,overcast --fps 1/2 --q 4 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const streams::StreamScan scan = streams::scanStreamFile(out);
  ASSERT_TRUE(scan.errors.empty());
  ASSERT_TRUE(scan.descriptor);
  EXPECT_EQ(scan.descriptor->framesPerVariant, 4u);  // the command line wins over the file
  ASSERT_EQ(scan.descriptor->variants.size(), 2u);
  EXPECT_EQ(scan.descriptor->variants[1].name, "overcast");
  EXPECT_EQ(scan.descriptor->streams[0].width, 32);
  EXPECT_EQ(scan.descriptor->streams[1].width, 32);  // from the file
  EXPECT_EQ(scan.descriptor->streams[1].height, 16);
  EXPECT_EQ(scan.descriptor->gameFps.num, 1u);
  EXPECT_EQ(scan.descriptor->gameFps.den, 2u);
  fs::remove(out);
}

// `--cell-size` sizes the procedural terrain's cells as it does a picture's (it used to keep 10 m):
// the record, which holds the cell size the frames were lit with, says so.
TEST(AuthorCli, ProceduralTerrainTakesTheCellSize) {
  const fs::path out = dir() / "cells.vbim";
  const Outcome r =
      run("author --procedural --size 32 --cell-size 30 --sky-width 32 --frame-count 2 --fps 1 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const Outcome info = run("info " + out.string());
  ASSERT_EQ(info.status, 0) << info.out;
  EXPECT_NE(info.out.find("terrain procedural, 32x32 texels of 30.0 m"), std::string::npos) << info.out;
  fs::remove(out);
}

// A real DEM of 95x90 geographic cells (resampled to 95x139 square ones): neither side is whole
// macroblocks, so it is cropped (centred) or padded, with a note; colour maps on the DEM file's own
// grid are resampled with it, maps of another size refused.
TEST(AuthorCli, ARealDemIsFittedToMacroblocksAndItsAlbedoFollows) {
  const std::string dem = std::string(VBIM_SOURCE_DIR) + "/tests/lighting/data/luxembourg_elev.tif";
  const fs::path onFileGrid = dir() / "lux_albedo.png", other = dir() / "other_albedo.png";
  writeImage(onFileGrid, 95, 90, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(95 * 90 * 3, 120));
  writeImage(other, 95, 139 / 2, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(95 * 69 * 3, 120));
  const std::string small = " --sky-width 32 --frame-count 2 --fps 1 --sun-azimuth 135 --sun-elevation 20";
  const fs::path out = dir() / "lux.vbim";

  Outcome r = run("author --terrain " + dem + " --albedo " + onFileGrid.string() + small + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("cropped from 95x139 to 80x128 texels (whole 16x16 macroblocks), centred: first kept texel "
                       "(7, 5)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lux_albedo.png: 95x90 on the heightfield file's grid, resampled with it to 80x128"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lightmap 80x128"), std::string::npos) << r.out;
  fs::remove(out);

  r = run("author --terrain " + dem + " --terrain-fit pad" + small + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("padded from 95x139 to 96x144 texels"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lightmap 96x144"), std::string::npos) << r.out;
  fs::remove(out);

  r = run("author --terrain " + dem + " --albedo " + other.string() + small + " --out " + out.string());
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("other_albedo.png: colour map is 95x69; expected the terrain's size 80x128 or the heightfield "
                       "file's 95x90"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(streamFiles().empty());
}

// Shadow rays are the default; --no-shadow-rays brings the sheared lines back. The record holds
// every lighting.* value the frames were lit with.
TEST(AuthorCli, ShadowRaysByDefaultAndNoShadowRaysTurnsThemOff) {
  const fs::path out = dir() / "rays.vbim";
  for (const bool off : {false, true}) {
    const Outcome r = run("author --procedural --size 32 --sky-width 32 --frame-count 2 --fps 1 --force" +
                          std::string(off ? " --no-shadow-rays" : "") + " --out " + out.string());
    ASSERT_EQ(r.status, 0) << r.out;
    const Outcome info = run("info --json " + out.string());
    ASSERT_EQ(info.status, 0) << info.out;
    const nlohmann::json record = nlohmann::json::parse(info.out)["authoring"];
    EXPECT_EQ(record["variants"][0]["lighting"]["lighting.shadow_rays"], !off) << info.out;
  }
  fs::remove(out);
}

struct BadCase {
  std::string name, args, words;
};

TEST(AuthorCli, BadInputsFailClearlyAndLeaveNothing) {
  const fs::path rgb = dir() / "rgb.png", nan = dir() / "nan.exr", odd = dir() / "odd.png", hf = dir() / "hf.png",
                 albedo = dir() / "albedo.png", junk = dir() / "junk.png", badCfg = dir() / "bad.toml";
  writeImage(rgb, 32, 32, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(32 * 32 * 3, 100));
  std::vector<float> heights(32 * 32, 1.0f);
  heights[5 * 32 + 7] = std::numeric_limits<float>::quiet_NaN();
  writeImage(nan, 32, 32, 1, OIIO::TypeDesc::FLOAT, heights);
  writeRidge(odd, 40, 32);
  writeRidge(hf, 32, 32);
  writeImage(albedo, 16, 16, 3, OIIO::TypeDesc::UINT8, std::vector<std::uint8_t>(16 * 16 * 3, 100));
  std::ofstream(junk) << "not an image";
  std::ofstream(badCfg) << "[lighting]\nlatitude_deg = 120\n";
  const std::string small = " --sky-width 32 --frame-count 2 --fps 1";
  const std::vector<BadCase> cases = {
      {"RGB heightfield", "--terrain " + rgb.string() + small, "rgb.png"},
      {"NaN height", "--terrain " + nan.string() + small, "nan.exr"},
      {"size not whole macroblocks", "--terrain " + odd.string() + " --terrain-fit none" + small, "multiple of 16"},
      {"unknown fit", "--terrain " + odd.string() + " --terrain-fit stretch" + small, "--terrain-fit"},
      {"unreadable heightfield", "--terrain " + junk.string() + small, "junk.png"},
      {"missing heightfield", "--terrain " + (dir() / "absent.png").string() + small, "absent.png"},
      {"albedo of another size", "--terrain " + hf.string() + " --albedo " + albedo.string() + small, "albedo.png"},
      {"latitude above 90", "--procedural --size 32 --latitude 91" + small, "lighting.latitude_deg"},
      {"latitude below -90", "--procedural --size 32 --latitude -90.5" + small, "lighting.latitude_deg"},
      {"latitude from a config file", "--procedural --size 32 --lighting-config " + badCfg.string() + small,
       "latitude_deg"},
      {"zero frames", "--procedural --size 32 --sky-width 32 --frame-count 0 --fps 1", "lighting.frames"},
      {"sky not whole macroblocks", "--procedural --size 32 --sky-width 48 --frame-count 2 --fps 1", "sky_width"},
      {"unknown weather", "--procedural --size 32 --weather clear,foggy" + small, "'foggy'"},
      {"terrain and frames", "--procedural --frames 'x_%04d.png'" + small, "excludes --frames"},
      {"terrain and procedural", "--procedural --terrain " + hf.string() + small, "exclude each other"},
  };
  const fs::path out = dir() / "bad.vbim";
  for (const BadCase& c : cases) {
    for (const bool existing : {false, true}) {
      if (existing) std::ofstream(out) << "old";
      // An existing output is replaced only with --force; a failed run must leave it as it was.
      const Outcome r = run("author " + c.args + " --out " + out.string() + (existing ? " --force" : ""));
      EXPECT_NE(r.status, 0) << c.name << "\n" << r.out;
      EXPECT_NE(r.out.find(c.words), std::string::npos) << c.name << ": expected '" << c.words << "' in\n" << r.out;
      if (existing) {
        std::ifstream in(out);
        std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(content, "old") << c.name << ": an existing output was touched";
        fs::remove(out);
      }
      EXPECT_TRUE(streamFiles().empty()) << c.name << ": left " << streamFiles().front();
    }
  }
}

}  // namespace
}  // namespace vbim::lighting
