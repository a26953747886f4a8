#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "imageio/image_reader.hpp"
#include "imageio/png_writer.hpp"
#include "imageio/rgba8.hpp"
#include "player/run_dir_reader.hpp"
#include "render/contact_sheet.hpp"
#include "render/error.hpp"
#include "render/render_run.hpp"
#include "render/video_writer.hpp"
#include "render_test_scene.hpp"
#include "tests/support/run_command.hpp"

namespace vbim::render {
namespace {

namespace fs = std::filesystem;
using player::readRunDir;
using player::RunDir;

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("vbim_render_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

RunRenderRequest smallRequest() {
  RunRenderRequest r;
  r.settings = test::smallSettings();
  r.terrain.cellSize = 20;
  r.day = test::smallDay();
  r.videoFps = 2;
  r.sheetThumbWidth = 48;
  return r;
}

// A run directory as `vbim play --every 60` writes it: frames at vsync 0, 60, 120, and a timeline
// with a stall between 60 and 120; from vsync `branchAt` on, the timeline shows variant `branchTo`.
// Before vsync `firstFrameAt` no frame has arrived nor is due (due_seq and target_seq -1).
fs::path fakeRun(int branchAt = 1000, int branchTo = 1, int firstFrameAt = 0) {
  const fs::path run = freshDir("run");
  fs::create_directories(run / "frames");
  for (int k = 0; k < 3; ++k) {
    const test::StreamedFrame f = test::streamedFrame(10 + k);
    char name[64];
    std::snprintf(name, sizeof name, "%06d.png", k * 60);
    imageio::writePng(run / "frames" / ("lightmap_" + std::string(name)), imageio::rgbOf(f.lightmap).view());
    imageio::writePng(run / "frames" / ("sky_" + std::string(name)), imageio::rgbOf(f.sky).view());
  }
  std::ofstream t(run / "timeline.csv");
  t << "vsync,time_s,hash,due_seq,target_seq,variant,fix,pop,behind,catch_up,snapped,sky_target_seq,sky_pop,lag,"
       "sky_lag,ring_banks,gs_busy_ticks\n";
  for (int v = 0; v <= 120; ++v) {
    const bool behind = v > 70 && v < 90, catchUp = v >= 90 && v < 100;
    const int seq = v < firstFrameAt ? -1 : 10 + v / 60;
    t << v << "," << v / 60.0 << ",0," << seq << "," << seq << "," << (v >= branchAt ? branchTo : 0) << ",0,0,"
      << behind << "," << catchUp << ",0,-1,0,0,0,0,0\n";
  }
  return run;
}

TEST(RenderRun, WritesFramesSheetVideoAndSummary) {
  const fs::path run = fakeRun();
  const fs::path out = freshDir("out");
  const RunDir dir = readRunDir(run);
  ASSERT_EQ(dir.frames.size(), 3u);
  EXPECT_EQ(dir.timeline.size(), 121u);
  EXPECT_TRUE(dir.timeline.at(80).behind);
  int calls = 0;
  const RunRenderResult r = renderRun(dir, smallRequest(), out, [&](int, int) { ++calls; });
  EXPECT_EQ(r.frames, 3);
  EXPECT_EQ(calls, 3);
  for (const char* f : {"frames/render_000000.png", "frames/render_000060.png", "frames/render_000120.png",
                        "contact_sheet.png", "playback.mp4", "render.json"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_GT(fs::file_size(out / "playback.mp4"), 1000u);
  // The tile of vsync 120 covers the stall: its frame is red.
  const Rgba8Image sheet = imageio::readRgba8(out / "contact_sheet.png");
  const int tile3x = 4 + 2 * (48 + 6 + 4);
  const std::uint8_t* border = sheet.row(5) + (tile3x + 1) * 4;
  EXPECT_EQ(border[0], 220);
  EXPECT_EQ(border[1], 20);
  const std::uint8_t* firstBorder = sheet.row(5) + (4 + 1) * 4;
  EXPECT_EQ(firstBorder[0], 90) << "the first tile is on time";
  fs::remove_all(run);
  fs::remove_all(out);
}

// Before the first frame has arrived the GS shows nothing: the first tile is black and framed and
// labelled "waiting", not "on time" (issue #33: the demo's first tile, during its spin-up stall); the
// next tile, whose picture shows a frame, is on time although its interval began waiting.
TEST(RenderRun, TilesBeforeTheFirstFrameAreWaiting) {
  const fs::path run = fakeRun(1000, 1, 30);
  const fs::path out = freshDir("waiting");
  renderRun(readRunDir(run), smallRequest(), out, nullptr);
  const Rgba8Image sheet = imageio::readRgba8(out / "contact_sheet.png");
  const auto borderAt = [&](int tile) {
    const std::uint8_t* p = sheet.row(5) + (4 + tile * (48 + 6 + 4) + 1) * 4;
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  EXPECT_EQ(borderAt(0), (std::array<int, 3>{70, 170, 80})) << "the first tile is waiting";
  EXPECT_EQ(borderAt(1), (std::array<int, 3>{90, 90, 90})) << "the second tile shows a frame, on time";
  EXPECT_EQ(borderAt(2), (std::array<int, 3>{220, 20, 20})) << "the third covers the stall";
  // Without that start the first tile is on time (WritesFramesSheetVideoAndSummary), never waiting.
  fs::remove_all(run);
  fs::remove_all(out);
}

// playback.mp4 plays at the run's speed: the fake run's 121 vsyncs (2.02 s) play in about 2 s,
// not as three frames at the video's rate (0.3 s at 10 frames/s) (issue #33).
TEST(RenderRun, VideoPlaysAtTheRunsSpeed) {
  const fs::path run = fakeRun();
  const fs::path out = freshDir("speed");
  RunRenderRequest req = smallRequest();
  req.videoFps = 10;
  const RunRenderResult r = renderRun(readRunDir(run), req, out, nullptr);
  EXPECT_EQ(r.videoFrames, 3);
  EXPECT_NEAR(r.videoSeconds, 2.1, 1e-9);  // frames at 0, 1 and 2 s; the last lasts one tick of 0.1 s
  const auto probe = vbim::testing::runCommand("ffprobe -v error -show_entries format=duration -of csv=p=0 " +
                                               (out / "playback.mp4").string());
  ASSERT_EQ(probe.status, 0) << probe.output;
  EXPECT_NEAR(std::stod(probe.output), 2.02, 0.1) << probe.output;
  const auto frames = vbim::testing::runCommand(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 " +
      (out / "playback.mp4").string());
  ASSERT_EQ(frames.status, 0) << frames.output;
  EXPECT_EQ(std::stoi(frames.output), 3) << frames.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out / "render.json"));
  EXPECT_EQ(j["video"]["frames"], 3);
  EXPECT_EQ(j["video"]["clock_fps"], 10);
  EXPECT_NEAR(j["video"]["to_s"].get<double>(), 121 / 60.0, 1e-9);
  fs::remove_all(run);
  fs::remove_all(out);
}

// Each saved frame lasts until the next; one that falls on the tick of the frame before is left out.
TEST(VideoSlots, FramesLastUntilTheNextAndTheLastUntilTheEnd) {
  const std::vector<VideoSlot> s = videoSlots({4.0, 8.0, 8.02, 12.0}, 60.0, 10);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_TRUE(s[0].shown);
  EXPECT_EQ(s[0].pts, 0);
  EXPECT_EQ(s[0].duration, 40);
  EXPECT_TRUE(s[1].shown);
  EXPECT_EQ(s[1].pts, 40);
  EXPECT_EQ(s[1].duration, 40);
  EXPECT_FALSE(s[2].shown) << "8.02 s is on 8.0 s's tick at 10 ticks/s";
  EXPECT_EQ(s[3].pts, 80);
  EXPECT_EQ(s[3].duration, 480);
  // A last frame left out: the one before holds until the end.
  const std::vector<VideoSlot> t = videoSlots({0.0, 1.0, 1.01}, 3.0, 10);
  EXPECT_FALSE(t[2].shown);
  EXPECT_EQ(t[1].duration, 20);
  EXPECT_THROW(videoSlots({1.0, 0.5}, 3.0, 10), RenderError);
  EXPECT_THROW(videoSlots({1.0, 2.0}, 1.5, 10), RenderError);
}

nlohmann::json renderJsonOf(const RunDir& dir, const RunRenderRequest& req, const std::string& name) {
  const fs::path out = freshDir(name);
  renderRun(dir, req, out, nullptr);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(out / "render.json"));
  fs::remove_all(out);
  return j;
}

// After a branch the frames show another weather: each is lit with its own variant's settings
// (render once lit every frame as the first variant).
TEST(RenderRun, FramesAfterABranchAreLitAsTheVariantTheyShow) {
  const fs::path run = fakeRun(100);
  const RunDir dir = readRunDir(run);
  RunRenderRequest same = smallRequest();
  same.video = false;
  same.variantDays = {same.day, same.day};
  RunRenderRequest weather = same;
  lighting::DayCycleParams overcast = same.day;
  overcast.turbidity = 6;
  overcast.sunKlux *= 0.4;
  weather.variantDays = {same.day, overcast};
  const nlohmann::json a = renderJsonOf(dir, same, "same");
  const nlohmann::json b = renderJsonOf(dir, weather, "weather");
  ASSERT_EQ(a["frames"].size(), 3u);
  ASSERT_EQ(b["frames"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(b["frames"][i]["variant"], i == 2 ? 1 : 0) << i;
    if (i < 2) {
      EXPECT_EQ(a["frames"][i], b["frames"][i]) << "frame " << i << " is variant 0 in both";
    } else {
      // Lit as variant 1: a hazier, 0.4x sun. The lightmap is the same, so the decoded sun is dimmer.
      EXPECT_LT(b["frames"][i]["sun_irradiance"][0].get<double>(),
                0.8 * a["frames"][i]["sun_irradiance"][0].get<double>())
          << a["frames"][i].dump() << "\n"
          << b["frames"][i].dump();
    }
  }
  // A timeline showing a variant the record does not have: the file, the vsync and the count.
  RunRenderRequest oneVariant = same;
  oneVariant.variantDays = {same.day};
  oneVariant.settingsFrom = "authoring.json";
  try {
    renderRun(dir, oneVariant, freshDir("one"), nullptr);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("timeline.csv: vsync 120 shows variant 1, but authoring.json records 1 variant(s)"),
              std::string::npos)
        << m;
  }
  // Without per-variant settings (no record, or --lighting-config) every frame has `day`'s lighting.
  RunRenderRequest single = same;
  single.variantDays.clear();
  const nlohmann::json c = renderJsonOf(dir, single, "single");
  EXPECT_EQ(c["frames"][2]["variant"], 1);
  EXPECT_EQ(c["frames"][2]["sky_irradiance"], a["frames"][2]["sky_irradiance"]);
  fs::remove_all(run);
  fs::remove_all(fs::temp_directory_path() / ("vbim_render_test_one_" + std::to_string(::getpid())));
}

TEST(RenderRun, RunWithoutFramesIsAClearError) {
  const fs::path run = freshDir("empty");
  std::ofstream(run / "timeline.csv") << "vsync,time_s\n";
  try {
    readRunDir(run);
    FAIL() << "expected vbim::Error";
  } catch (const Error& e) {  // the reader is player/run_dir_reader.hpp
    EXPECT_NE(std::string(e.what()).find("no frames"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readRunDir(run / "missing"), Error);
  fs::remove_all(run);
}

TEST(RenderRun, BadTimelineRowNamesTheLine) {
  const fs::path run = fakeRun();
  std::ofstream(run / "timeline.csv", std::ios::app) << "121,oops\n";
  try {
    readRunDir(run);
    FAIL() << "expected vbim::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("timeline.csv:123"), std::string::npos) << e.what();
  }
  fs::remove_all(run);
}

TEST(RenderRun, NoContextFailsBeforeWriting) {
  const fs::path run = fakeRun();
  const fs::path out = freshDir("nocontext");
  RunRenderRequest r = smallRequest();
  r.contextFactory = []() -> std::unique_ptr<GlContext> { throw RenderError("no GL context available: test"); };
  EXPECT_THROW(renderRun(readRunDir(run), r, out), RenderError);
  EXPECT_FALSE(fs::exists(out / "frames"));
  fs::remove_all(run);
  fs::remove_all(out);
}

}  // namespace
}  // namespace vbim::render
