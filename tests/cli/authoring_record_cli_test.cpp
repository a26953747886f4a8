// A stream that carries how it was authored (issue #15 item 7): `vbim info` shows the record,
// `vbim play` copies it into the run (authoring.json), `vbim render` lights the recorded terrain at
// the recorded hours with no option repeated, options given still win, and a run without a record
// keeps the old defaults with a note.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using vbim::testing::readFileBytes;
using vbim::testing::runCommand;

class AuthoringRecordCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("vbim_authoring_record_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Not the samples' day: 10 frames from 4 h to 22 h (one every 2 h), 10 m cells.
    const auto a = vbim(
        "author --procedural --size 64 --sky-width 32 --frame-count 10 --start-hour 4 --end-hour 22 "
        "--fps 1 --out " +
        p("day.vbim") + " --iso " + p("disc.iso"));
    ASSERT_EQ(a.status, 0) << a.output;
    const auto play = vbim("play " + p("disc.iso") + " --duration 8s --every 60 --no-trace --out " + p("run"));
    ASSERT_EQ(play.status, 0) << play.output;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static vbim::testing::CommandResult vbim(const std::string& args) {
    return runCommand(std::string(VBIM_BINARY) + " " + args);
  }
  static std::string p(const std::string& name) { return (dir_ / name).string(); }
  static json render(const std::string& run, const std::string& out, const std::string& extra = "") {
    const auto r = vbim("render " + run + " --out " + p(out) + " --no-video --width 96 --height 64 " + extra);
    EXPECT_EQ(r.status, 0) << r.output;
    std::ifstream in(dir_ / out / "render.json");
    return json::parse(in, nullptr, false);
  }

  static fs::path dir_;
};
fs::path AuthoringRecordCli::dir_;

TEST_F(AuthoringRecordCli, InfoShowsTheRecordAndPlayCopiesIt) {
  const auto text = vbim("info " + p("day.vbim"));
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("authoring: technique-a by vbim "), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("terrain procedural, 64x64 texels of 10.0 m"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("day 4.0 h to 22.0 h, 10 frames per variant (frame 1 at 6.00 h, last at 22.00 h)"),
            std::string::npos)
      << text.output;
  const auto js = vbim("info --json " + p("disc.iso"));
  ASSERT_EQ(js.status, 0) << js.output;
  const json record = json::parse(js.output)["authoring"];
  EXPECT_EQ(record["day"]["frame_hours"].size(), 10u);
  EXPECT_EQ(record["day"]["frame_hours"][3], 10.0);
  EXPECT_EQ(record["variants"][0]["lighting"]["lighting.frames"], 10);
  std::ifstream in(dir_ / "run" / "authoring.json");
  EXPECT_EQ(json::parse(in, nullptr, false), record);
}

TEST_F(AuthoringRecordCli, RenderUsesTheRecordedTerrainAndHours) {
  const json r = render(p("run"), "pictures");
  ASSERT_FALSE(r.is_discarded());
  EXPECT_EQ(r["settings_from"], p("run") + "/authoring.json");
  EXPECT_EQ(r["cell_size_m"], 10.0);
  EXPECT_EQ(r["terrain_size"], json({64, 64}));
  EXPECT_EQ(r["day"]["frames"], 10);
  int checked = 0;
  for (const json& f : r["frames"]) {
    const int seq = f["seq"].get<int>();
    if (seq < 0) continue;
    EXPECT_DOUBLE_EQ(f["hour"].get<double>(), 4.0 + 2.0 * seq) << f.dump();  // frame k holds 4 + 2k h
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST_F(AuthoringRecordCli, OptionsGivenWinOverTheRecord) {
  const json r = render(p("run"), "pictures_cell", "--cell-size 25");
  EXPECT_EQ(r["cell_size_m"], 25.0);
  EXPECT_EQ(r["day"]["frames"], 10);  // the rest still from the record
}

// A stream of two weathers played with a branch: the frames after it are lit as the overcast
// variant, and --lighting-config lays its keys over both variants.
TEST_F(AuthoringRecordCli, FramesAfterABranchAreLitAsTheirWeather) {
  const auto a = vbim(
      "author --procedural --size 64 --sky-width 32 --frame-count 10 --start-hour 4 --end-hour 22 --fps 1 "
      "--weather clear,overcast --out " +
      p("weather.vbim"));
  ASSERT_EQ(a.status, 0) << a.output;
  const auto play = vbim("play " + p("weather.vbim") + " --duration 8s --branch 4s=1 --every 60 --no-trace --out " +
                         p("weather_run"));
  ASSERT_EQ(play.status, 0) << play.output;
  const json r = render(p("weather_run"), "pictures_weather");
  ASSERT_FALSE(r.is_discarded());
  // The renderer fits the stream's scale to the lighting it predicts from the settings: with each
  // frame's own weather the fit stays near 1 on both sides of the branch (lit with the clear
  // settings, the overcast frames fitted 0.51-0.87).
  int before = 0, after = 0;
  for (const json& f : r["frames"]) {
    if (f["seq"].get<int>() < 1) continue;  // none yet, and the 4 h frame is dawn: too dark to fit
    (f["variant"].get<int>() == 0 ? before : after) += 1;
    EXPECT_NEAR(f["stream_scale"].get<double>(), 1.0, 0.15) << f.dump();
  }
  EXPECT_GE(before, 2) << r.dump();
  EXPECT_GE(after, 2) << r.dump();
  // --lighting-config lays its keys over every variant's own settings. exposure_klux = 60 against
  // the recorded 120 (clear) and 192 (overcast: 1.6x, technique_a_stream.hpp) scales each fit by
  // 60 / 120 and 60 / 192.
  std::ofstream(p("exposure.toml")) << "[lighting]\nexposure_klux = 60.0\n";
  const json c = render(p("weather_run"), "pictures_weather_config", "--lighting-config " + p("exposure.toml"));
  ASSERT_FALSE(c.is_discarded());
  ASSERT_EQ(c["frames"].size(), r["frames"].size());
  for (std::size_t k = 0; k < r["frames"].size(); ++k) {
    const json& f = r["frames"][k];
    if (f["seq"].get<int>() < 1) continue;
    ASSERT_EQ(c["frames"][k]["variant"], f["variant"]);
    const double ratio = c["frames"][k]["stream_scale"].get<double>() / f["stream_scale"].get<double>();
    EXPECT_NEAR(ratio, f["variant"] == 0 ? 60.0 / 120 : 60.0 / 192, 0.03) << f.dump() << "\n" << c["frames"][k].dump();
  }
}

TEST_F(AuthoringRecordCli, ARunWithoutARecordKeepsTheDefaultsWithANote) {
  fs::copy(dir_ / "run", dir_ / "bare_run", fs::copy_options::recursive);
  fs::remove(dir_ / "bare_run" / "authoring.json");
  const auto out =
      vbim("render " + p("bare_run") + " --out " + p("pictures_bare") + " --no-video --width 96 --height 64");
  ASSERT_EQ(out.status, 0) << out.output;
  EXPECT_NE(out.output.find("note: " + p("bare_run") + " has no authoring.json"), std::string::npos) << out.output;
  std::ifstream in(dir_ / "pictures_bare" / "render.json");
  const json r = json::parse(in, nullptr, false);
  EXPECT_EQ(r["settings_from"], "defaults");
  EXPECT_EQ(r["cell_size_m"], 20.0);
  EXPECT_EQ(r["day"]["frames"], 24);
}

TEST_F(AuthoringRecordCli, ARecordThatCannotBeReadIsNamed) {
  fs::copy(dir_ / "run", dir_ / "bad_run", fs::copy_options::recursive);
  std::ofstream(dir_ / "bad_run" / "authoring.json") << R"({"record": "vbim-authoring", "record_version": 99})";
  const auto out = vbim("render " + p("bad_run") + " --out " + p("pictures_badrec") + " --no-video");
  EXPECT_EQ(out.status, 2) << out.output;
  EXPECT_NE(out.output.find(p("bad_run") + "/authoring.json: authoring record version 99 is newer"), std::string::npos)
      << out.output;
  EXPECT_FALSE(fs::exists(dir_ / "pictures_badrec"));
}

}  // namespace

namespace {

// Streams made from image files or by the synthetic generator carry a record too: what is known of
// them (source, frame sizes and times), with no terrain; render notes that and keeps its defaults.
TEST(AuthoringRecordFrames, SyntheticAndImageSequenceStreamsCarryWhatIsKnown) {
  const fs::path dir = fs::temp_directory_path() / ("vbim_authoring_frames_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto vbim = [](const std::string& args) { return runCommand(std::string(VBIM_BINARY) + " " + args); };
  const std::string d = dir.string();
  ASSERT_EQ(vbim("author --synthetic clear,overcast --synthetic-frames 4 --fps 2 --out " + d + "/syn.vbim").status, 0);
  const auto info = vbim("info " + d + "/syn.vbim");
  EXPECT_NE(info.output.find("authoring: synthetic by vbim "), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("frames: lightmap [256,256], sky [128,64]; 4 per variant, one every 0.5 s"),
            std::string::npos)
      << info.output;
  EXPECT_NE(info.output.find("variant 'overcast'"), std::string::npos) << info.output;

  const auto lm = vbim("lightmap --size 64 --sky-width 32 --frames 2 --out " + d + "/lm");
  ASSERT_EQ(lm.status, 0) << lm.output;
  const auto seq = vbim("author --frames '" + d + "/lm/lightmap_%04d.png' --sky '" + d +
                        "/lm/sky_%04d.png' --fps 1 --out " + d + "/seq.vbim");
  ASSERT_EQ(seq.status, 0) << seq.output;
  const auto json = vbim("info --json " + d + "/seq.vbim");
  const nlohmann::json j = nlohmann::json::parse(json.output, nullptr, false);
  ASSERT_TRUE(j.is_object()) << json.output;
  EXPECT_EQ(j["authoring"]["source"], "image-sequence");
  EXPECT_EQ(j["authoring"]["frames"]["lightmap"], nlohmann::json({64, 64}));
  EXPECT_EQ(j["authoring"]["stream"]["frames_per_variant"], 2);
  EXPECT_EQ(j["authoring"]["variants"][0]["first_lightmap"], "lightmap_0000.png");

  const auto play = vbim("play " + d + "/syn.vbim --duration 3s --every 60 --no-trace --out " + d + "/run");
  ASSERT_EQ(play.status, 0) << play.output;
  EXPECT_TRUE(fs::exists(dir / "run" / "authoring.json"));
  const auto render = vbim("render " + d + "/run --no-video --width 64 --height 36 --out " + d + "/pictures");
  EXPECT_EQ(render.status, 0) << render.output;
  EXPECT_NE(render.output.find("records a stream made from synthetic frames, with no terrain"), std::string::npos)
      << render.output;
  fs::remove_all(dir);
}

}  // namespace
