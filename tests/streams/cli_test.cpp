// The command line as a user meets it: vbim author / vbim info, Debian's ffprobe and ffmpeg on the
// result, and the bad inputs of issue #4 (message naming the file and problem, non-zero exit, nothing
// under the final name).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include "tests/support/run_command.hpp"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>

#include "streams/authoring/synthetic_day.hpp"
#include "tests/streams/stream_fixture.hpp"

namespace vbim::streams {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

struct Outcome {
  int status = -1;
  std::string out;  // stdout and stderr together
};

Outcome run(const std::string& cmd) {
  const vbim::testing::CommandResult r = vbim::testing::runCommand(cmd);
  return {r.status, r.output};
}

std::string vbim() {
  return VBIM_BINARY;
}

void writeRgb8(const fs::path& path, int w, int h, const std::vector<std::uint8_t>& px) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  ASSERT_TRUE(out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  out->close();
}

void writePng(const fs::path& path, int w, int h, int seed) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        px[(static_cast<std::size_t>(y) * w + x) * 3 + c] =
            static_cast<std::uint8_t>((x * 3 + y * 2 + c * 40 + seed * 9) & 0xFF);
  writeRgb8(path, w, h, px);
}

// Uniform noise: the heaviest content for the encoder.
void writeNoisePng(const fs::path& path, int w, int h, std::uint32_t seed) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 3);
  for (std::uint8_t& v : px) {
    seed = seed * 1664525u + 1013904223u;
    v = static_cast<std::uint8_t>(seed >> 24);
  }
  writeRgb8(path, w, h, px);
}

void writeExr(const fs::path& path, const FloatRgbImage& img) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::HALF);
  ASSERT_TRUE(out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, img.rgb.data()));
  out->close();
}

// A stream authored through the CLI from EXR files: two variants, each lightmap + sky.
class StreamsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    SyntheticDay day;
    day.width = day.height = 64;
    day.skyWidth = 32;
    day.skyHeight = 16;
    day.frames = 6;
    for (const char* w : {"clear", "overcast"}) {
      day.weather = w;
      fs::create_directories(*dir_ / w);
      for (std::uint32_t f = 0; f < day.frames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "lm_%04u.exr", f);
        writeExr(*dir_ / w / name, syntheticLightmap(day, f));
        std::snprintf(name, sizeof name, "sky_%04u.exr", f);
        writeExr(*dir_ / w / name, syntheticSky(day, f));
      }
    }
    const fs::path d = dir_->path();
    authored_ = new Outcome(run(vbim() + " author --frames '" + (d / "clear/lm_%04d.exr").string() + "' --sky '" +
                                (d / "clear/sky_%04d.exr").string() +
                                "' --name clear --variant 'overcast=" + (d / "overcast/lm_%04d.exr").string() +
                                "' --variant-sky 'overcast=" + (d / "overcast/sky_%04d.exr").string() +
                                "' --fps 1/2 --loop 2 --out " + (d / "day.vbim").string()));
  }
  static void TearDownTestSuite() {
    delete authored_;
    delete dir_;
  }
  static fs::path stream() { return *dir_ / "day.vbim"; }
  static TempDir* dir_;
  static Outcome* authored_;
};
TempDir* StreamsCli::dir_ = nullptr;
Outcome* StreamsCli::authored_ = nullptr;

TEST_F(StreamsCli, AuthorWritesTheStreamAndInfoDescribesIt) {
  ASSERT_EQ(authored_->status, 0) << authored_->out;
  EXPECT_EQ(authored_->out.find("container time"), std::string::npos) << "light frames need no spacing\n"
                                                                      << authored_->out;
  const Outcome info = run(vbim() + " info --json " + stream().string());
  ASSERT_EQ(info.status, 0) << info.out;
  const auto j = nlohmann::json::parse(info.out);
  EXPECT_TRUE(j["every_pack_2048"].get<bool>());
  EXPECT_EQ(j["descriptor"]["game_fps"]["num"], 1);
  EXPECT_EQ(j["descriptor"]["game_fps"]["den"], 2);
  EXPECT_EQ(j["descriptor"]["loop_frame"], 2);
  EXPECT_EQ(j["descriptor"]["variants"][1]["name"], "overcast");
  EXPECT_EQ(j["descriptor"]["variants"][1]["first_frame"], 6);
  ASSERT_EQ(j["streams"].size(), 2u);
  EXPECT_EQ(j["streams"][0]["id"], "0xE0");
  EXPECT_EQ(j["streams"][0]["pictures"], 12);
  EXPECT_EQ(j["streams"][1]["pictures"], 12);
  EXPECT_TRUE(j["errors"].empty());
  const Outcome text = run(vbim() + " info " + stream().string());
  EXPECT_EQ(text.status, 0);
  for (const char* words : {"every pack is 2048 bytes", "worst run", "variant 'overcast'", "sectors per frame"})
    EXPECT_NE(text.out.find(words), std::string::npos) << words << "\n" << text.out;
}

TEST_F(StreamsCli, FfprobeListsExactlyTwoVideoStreamsOfIntraPictures) {
  ASSERT_EQ(authored_->status, 0) << authored_->out;
  const Outcome streams =
      run("ffprobe -v error -show_entries stream=id,codec_type,codec_name,width,height -of json " + stream().string());
  ASSERT_EQ(streams.status, 0) << streams.out << "\n(ffprobe comes with Debian's ffmpeg package: scripts/setup.sh)";
  const auto js = nlohmann::json::parse(streams.out).at("streams");
  ASSERT_EQ(js.size(), 2u) << streams.out;
  const char* ids[] = {"0x1e0", "0x1e1"};
  const int widths[] = {64, 32};
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(js[i]["codec_type"], "video");
    EXPECT_EQ(js[i]["codec_name"], "mpeg2video");
    EXPECT_EQ(js[i]["id"], ids[i]);
    EXPECT_EQ(js[i]["width"], widths[i]);
  }
  const Outcome frames =
      run("ffprobe -v error -show_entries frame=pict_type,stream_index -of json " + stream().string());
  ASSERT_EQ(frames.status, 0) << frames.out;
  int intra[2] = {0, 0}, other = 0;
  const auto jf = nlohmann::json::parse(frames.out);
  for (const auto& f : jf["frames"]) {
    if (f["pict_type"] == "I")
      ++intra[f["stream_index"].get<int>()];
    else
      ++other;
  }
  EXPECT_EQ(intra[0], 12);
  EXPECT_EQ(intra[1], 12);
  EXPECT_EQ(other, 0) << frames.out;
  const Outcome decode = run("ffmpeg -v error -nostdin -i " + stream().string() + " -map 0 -f null -");
  EXPECT_EQ(decode.status, 0) << decode.out;
}

// Frames heavier than the DVD mux rate sends in one container period (here ~400 KB of noise at
// q 1 against ~50 KB per 25 fps period) are spaced whole periods apart: vbim author says by how
// many, and vbim info's PTS step agrees.
TEST(StreamsCliStretch, AuthorSaysWhenItSpacesHeavyFramesApart) {
  TempDir dir;
  writeNoisePng(dir / "lm_0000.png", 512, 512, 1);
  writeNoisePng(dir / "lm_0001.png", 512, 512, 2);
  const fs::path out = dir / "noise.vbim";
  const Outcome r =
      run(vbim() + " author --frames " + (dir / "lm_%04d.png").string() + " --fps 1 --q 1 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::size_t at = r.out.find("container time: frames ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const int periods = std::atoi(r.out.c_str() + at + std::strlen("container time: frames "));
  EXPECT_GT(periods, 1) << r.out;
  EXPECT_NE(r.out.find("periods apart"), std::string::npos) << r.out;
  const Outcome info = run(vbim() + " info --json " + out.string());
  ASSERT_EQ(info.status, 0) << info.out;
  EXPECT_EQ(nlohmann::json::parse(info.out)["descriptor"]["pts_per_frame"], 3600 * periods);
}

TEST(StreamsCliBadInput, InfoRejectsAWrongFormatFileAndNamesIt) {
  TempDir dir;
  test::writeFile(dir / "x.png", std::vector<std::uint8_t>(5000, 0x42));
  const Outcome r = run(vbim() + " info " + (dir / "x.png").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("x.png"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("00 00 01 BA"), std::string::npos) << r.out;
  const Outcome missing = run(vbim() + " info " + (dir / "nothing.vbim").string());
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.out.find("nothing.vbim"), std::string::npos) << missing.out;
}

// MPEG that `vbim decode` reads but `vbim info` does not (no 2048-byte packs): the error says what
// the file is and how to remux it, the remuxed file is described, and play says what it lacks.
TEST(StreamsCliBadInput, InfoNamesElementaryAndMpeg1SystemStreamsAndHowToRemuxThem) {
  TempDir dir;
  const std::string source = "-f lavfi -i testsrc=size=64x64:rate=25 -t 0.4 -c:v mpeg2video -g 4 -bf 2 ";
  const fs::path es = dir / "clip.m2v";
  const fs::path system = dir / "clip.mpg";
  const fs::path vob = dir / "clip.vob";
  ASSERT_EQ(run("ffmpeg -nostdin -loglevel error -y " + source + "-f mpeg2video " + es.string()).status, 0);
  ASSERT_EQ(run("ffmpeg -nostdin -loglevel error -y " + source + "-f mpeg " + system.string()).status, 0);
  for (const auto& [file, kind] : {std::pair{es, "elementary stream"}, std::pair{system, "MPEG-1 system stream"}}) {
    const Outcome r = run(vbim() + " info " + file.string());
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(file.string()), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(kind), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("-f vob"), std::string::npos) << r.out;
    EXPECT_EQ(run(vbim() + " decode " + file.string() + " --format yuv --out " + (dir / "frames").string() + " --force")
                  .status,
              0);
  }
  ASSERT_EQ(run("ffmpeg -nostdin -loglevel quiet -y -i " + es.string() + " -c copy -f vob " + vob.string()).status, 0);
  const Outcome remuxed = run(vbim() + " info --json " + vob.string());
  ASSERT_EQ(remuxed.status, 0) << remuxed.out;
  EXPECT_EQ(nlohmann::json::parse(remuxed.out)["streams"][0]["pictures"], 10) << remuxed.out;
  // No playback descriptor: play refuses it and says what writes one; nothing is left behind.
  const Outcome play = run(vbim() + " play " + vob.string() + " --out " + (dir / "run").string());
  EXPECT_EQ(play.status, 2) << play.out;
  EXPECT_NE(play.out.find("`vbim author` writes"), std::string::npos) << play.out;
  EXPECT_FALSE(fs::exists(dir / "run"));
  // Damage that is no MPEG keeps the plain message.
  test::writeFile(dir / "x.bin", std::vector<std::uint8_t>(5000, 0x00));
  EXPECT_EQ(run(vbim() + " info " + (dir / "x.bin").string()).out.find("remux"), std::string::npos);
}

// Each case: files to create (name -> WxH), arguments, words the message must contain.
struct BadCase {
  const char* name;
  std::vector<std::pair<std::string, std::pair<int, int>>> files;
  std::string args;
  std::vector<std::string> words;
};

TEST(StreamsCliBadInput, AuthorFailsCleanlyAndLeavesNothingUnderTheFinalName) {
  const std::vector<BadCase> cases = {
      {"pattern matches no file", {}, "--frames D/lm_%04d.png", {"lm_%04d.png", "matches no file"}},
      {"missing directory", {}, "--frames D/nodir/lm_%04d.png", {"nodir", "does not exist"}},
      {"frames of different sizes",
       {{"lm_0000.png", {32, 32}}, {"lm_0001.png", {48, 32}}},
       "--frames D/lm_%04d.png",
       {"lm_0001.png", "48x32", "32x32"}},
      {"odd size", {{"lm_0000.png", {33, 32}}}, "--frames D/lm_%04d.png", {"lm_0000.png", "33x32", "multiples of 16"}},
      {"gap in the numbering",
       {{"lm_0000.png", {32, 32}}, {"lm_0002.png", {32, 32}}},
       "--frames D/lm_%04d.png",
       {"lm_0001.png", "missing"}},
      {"missing sky sequence",
       {{"lm_0000.png", {32, 32}}},
       "--frames D/lm_%04d.png --sky D/sky_%04d.png",
       {"sky_%04d.png", "matches no file"}},
      {"fewer sky frames",
       {{"lm_0000.png", {32, 32}}, {"lm_0001.png", {32, 32}}, {"sky_0000.png", {32, 16}}},
       "--frames D/lm_%04d.png --sky D/sky_%04d.png",
       {"2 lightmap frames but 1 sky frames", "sky_0000.png"}},
      {"variant without sky",
       {{"lm_0000.png", {32, 32}}, {"sky_0000.png", {32, 16}}, {"rain_0000.png", {32, 32}}},
       "--frames D/lm_%04d.png --sky D/sky_%04d.png --variant rain=D/rain_%04d.png",
       {"rain", "no sky sequence"}},
      {"not an image", {{"lm_0000.png", {0, 0}}}, "--frames D/lm_%04d.png", {"lm_0000.png", "cannot read the image"}},
  };
  for (const BadCase& c : cases) {
    TempDir dir;
    for (const auto& [file, size] : c.files) {
      if (size.first == 0)
        test::writeFile(dir / file, {'n', 'o', 'p', 'e'});
      else
        writePng(dir / file, size.first, size.second, 1);
    }
    std::string args = c.args;
    for (std::size_t p; (p = args.find("D/")) != std::string::npos;) args.replace(p, 1, dir.path().string());
    const fs::path out = dir / "out.vbim";
    const Outcome r = run(vbim() + " author " + args + " --fps 1 --out " + out.string());
    EXPECT_NE(r.status, 0) << c.name << "\n" << r.out;
    for (const std::string& w : c.words)
      EXPECT_NE(r.out.find(w), std::string::npos) << c.name << ": '" << w << "'\n" << r.out;
    EXPECT_FALSE(fs::exists(out)) << c.name;
    for (const auto& entry : fs::directory_iterator(dir.path()))
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
          << c.name << ": left " << entry.path();
  }
}

TEST(StreamsCliBadInput, UnwritableOutputNamesTheFileAndKeepsAnOldStream) {
  TempDir dir;
  writePng(dir / "lm_0000.png", 32, 32, 1);
  const std::string frames = " author --frames " + (dir / "lm_%04d.png").string() + " --fps 1 --out ";
  // The parent is a regular file, so no directory can be created there.
  test::writeFile(dir / "afile", {'x'});
  Outcome r = run(vbim() + frames + (dir / "afile" / "out.vbim").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("out.vbim"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("does not exist"), std::string::npos) << r.out;
  // The output is an existing directory.
  fs::create_directories(dir / "adir.vbim");
  r = run(vbim() + frames + (dir / "adir.vbim").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("is a directory"), std::string::npos) << r.out;
  // A failed run leaves an existing stream untouched.
  const std::vector<std::uint8_t> old = {1, 2, 3};
  test::writeFile(dir / "old.vbim", old);
  writePng(dir / "lm_0001.png", 48, 32, 2);
  r = run(vbim() + frames + (dir / "old.vbim").string());
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(test::readFile(dir / "old.vbim"), old);
}

}  // namespace
}  // namespace vbim::streams
