// `vbim lightmap` as a call (runs/lightmap_run.hpp): the procedural terrain's frames written with a
// progress call per frame and the summary, and a bad request or an existing output refused before
// any frame.
#include "runs/lightmap_run.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

LightmapRequest smallDay(const fs::path& out) {
  LightmapRequest r;
  r.terrain.procedural.size = 32;
  r.applyGiven = [](lighting::DayCycleParams& p) {
    p.frames = 2;
    p.skyWidth = 32;
  };
  r.out = out.string();
  return r;
}

TEST(LightmapRun, TheFramesAreWrittenAndSummed) {
  const fs::path dir = vbim::testing::testScratchDir("lightmap_run");
  const LightmapRequest r = smallDay(dir / "lm");
  std::vector<int> done;
  LightmapObserver observer;
  observer.onTerrainNote = [](const std::string& note) { ADD_FAILURE() << "procedural terrain, a note: " << note; };
  observer.onProgress = [&done](int d, int total) {
    EXPECT_EQ(total, 2);
    done.push_back(d);
  };
  EXPECT_EQ(lightmapRun(r, observer), "2 frames (32x32 lightmaps, 32x16 sky domes) in " + r.out);
  EXPECT_EQ(done, (std::vector<int>{0, 1, 2}));
  EXPECT_FALSE(fs::is_empty(r.out));
  // Again into the same directory: refused before any frame.
  done.clear();
  EXPECT_THROW(lightmapRun(r, observer), Error);
  EXPECT_TRUE(done.empty());
  fs::remove_all(dir);
}

TEST(LightmapRun, ABadFormatIsRefusedBeforeAnyOutput) {
  const fs::path dir = vbim::testing::testScratchDir("lightmap_run");
  LightmapRequest r = smallDay(dir / "lm");
  r.files.debug = "bogus";
  EXPECT_THROW(lightmapRun(r, {}), Error);
  EXPECT_FALSE(fs::exists(r.out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vbim::runs
