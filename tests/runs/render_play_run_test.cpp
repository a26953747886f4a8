// `vbim render` as a call (runs/render_play_run.hpp): what it refuses before any output (a run
// directory that is not one, a camera it cannot read), and a render that fails leaving no output
// directory, with the note of a run that does not say what terrain it shows. The pictures themselves
// are tests/render's; the command end to end is tests/cli's.
#include "runs/render_play_run.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "imageio/png_writer.hpp"
#include "imageio/rgba8.hpp"
#include "render/error.hpp"
#include "runtime/error.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

// A run directory as `vbim play --every 60 --out RUN` leaves it, without an authoring record: two
// 32x32 lightmaps and their skies, and the timeline of the vsyncs between them.
fs::path smallRun(const fs::path& dir) {
  const fs::path run = dir / "run";
  fs::create_directories(run / "frames");
  const Rgba8Image lightmap(32, 32), sky(32, 16);
  for (const char* vsync : {"000000", "000060"}) {
    imageio::writePng(run / "frames" / ("lightmap_" + std::string(vsync) + ".png"), imageio::rgbOf(lightmap).view());
    imageio::writePng(run / "frames" / ("sky_" + std::string(vsync) + ".png"), imageio::rgbOf(sky).view());
  }
  std::ofstream t(run / "timeline.csv");
  t << "vsync,time_s,hash,due_seq,target_seq,variant,fix,pop,behind,catch_up,snapped,sky_target_seq,sky_pop,lag,"
       "sky_lag,ring_banks,gs_busy_ticks\n";
  for (int v = 0; v <= 60; ++v) t << v << "," << v / 60.0 << ",0,0,0,0,0,0,0,0,0,-1,0,0,0,0,0\n";
  return run;
}

TEST(RenderPlayRun, ARunDirectoryThatIsNoneIsRefusedBeforeAnyOutput) {
  const fs::path dir = vbim::testing::testScratchDir("render_play_run");
  RenderPlayRequest r;
  r.run = (dir / "missing").string();
  r.out = (dir / "out").string();
  EXPECT_THROW(renderPlayRun(r, {}), Error);
  EXPECT_FALSE(fs::exists(r.out));
  // A camera it cannot read: refused before the run is read.
  r.run = smallRun(dir).string();
  r.camera = "1,2,three";
  EXPECT_THROW(renderPlayRun(r, {}), render::RenderError);
  EXPECT_FALSE(fs::exists(r.out));
  fs::remove_all(dir);
}

TEST(RenderPlayRun, ARenderThatFailsLeavesNoOutputAndTheNoteIsSaid) {
  const fs::path dir = vbim::testing::testScratchDir("render_play_run");
  RenderPlayRequest r;
  r.run = smallRun(dir).string();
  r.out = (dir / "out").string();
  r.options.values.contextFactory = []() -> std::unique_ptr<render::GlContext> {
    throw render::RenderError("no GL context available: test");
  };
  std::vector<std::string> notes;
  RenderPlayObserver observer;
  observer.onNote = [&notes](const std::string& note) { notes.push_back(note); };
  observer.onProgress = [](int, int) { ADD_FAILURE() << "no frame is rendered without a context"; };
  EXPECT_THROW(renderPlayRun(r, observer), render::RenderError);
  EXPECT_FALSE(fs::exists(r.out));
  ASSERT_EQ(notes.size(), 1u) << "a run without authoring.json: the terrain assumed is said";
  EXPECT_FALSE(notes[0].empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::runs
