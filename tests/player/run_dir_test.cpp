// The run directory through the test API: the files `vbim play` writes, from a Scenario's run, with
// the rows the Run records still there (the writer chains after the Run's own sink).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "player/report.hpp"
#include "player/run_dir.hpp"
#include "player/scenario.hpp"
#include "runtime/error.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::player {
namespace {

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(RunDir, ATestWritesTheFilesOfAPlayAndKeepsItsRows) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vbim-run-dir-test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run =
      Scenario::bareFile(testing::samplePath("day_clear.vbim")).seed(3).stall(0, fromMs(500)).start(fromMs(2'000));
  RunDirOptions options;
  options.every = 60;
  options.imageExtension = "raw";
  int pictures = 0;
  options.writeImage = [&](const std::filesystem::path& path, const Rgba8Image& texels) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(texels.pixels.data()), static_cast<std::streamsize>(texels.pixels.size()));
    ++pictures;
  };
  RunDirWriter writer(run->player(), dir, options);
  run->runToEnd();
  writer.finish();

  ASSERT_FALSE(run->rows().empty());
  std::string hashes;
  std::string timeline = timelineHeader();
  for (const VsyncRow& row : run->rows()) {
    hashes += hashesLine(row);
    timeline += timelineLine(row);
  }
  EXPECT_EQ(readText(dir / "hashes.txt"), hashes);
  EXPECT_EQ(readText(dir / "timeline.csv"), timeline);
  EXPECT_EQ(readText(dir / "stats.json"), run->statsJson());
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "lightmap_000000.raw"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "sky_000060.raw"));
  EXPECT_EQ(writer.images(), (static_cast<std::int64_t>(run->rows().size()) + 59) / 60);
  EXPECT_EQ(pictures, 2 * writer.images());
  EXPECT_FALSE(readText(dir / "arrivals.csv").empty());
  EXPECT_FALSE(readText(dir / "trace.json").empty());
  EXPECT_FALSE(readText(dir / "signals.vcd").empty());
  std::filesystem::remove_all(dir);
}

// The pictures written on their own thread (the default) are the files written on the
// simulation's thread, byte for byte, all there once finish() returns.
TEST(RunDir, PicturesOnTheirOwnThreadAreTheSameFiles) {
  const std::filesystem::path base =
      std::filesystem::temp_directory_path() / ("vbim-run-dir-pictures-" + std::to_string(::getpid()));
  std::filesystem::remove_all(base);
  for (const std::size_t queue : {std::size_t{0}, std::size_t{1}, std::size_t{8}}) {
    const std::filesystem::path dir = base / std::to_string(queue);
    std::filesystem::create_directories(dir);
    auto run = Scenario::bareFile(testing::samplePath("day_clear.vbim")).seed(3).start(fromMs(3'000));
    RunDirOptions options;
    options.every = 30;
    options.imageExtension = "raw";
    options.trace = false;
    options.pictureQueue = queue;
    options.writeImage = [](const std::filesystem::path& path, Rgba8Image& texels) {
      texels.pixels[3] ^= 1;  // the writer's copy: changing it must not reach the run
      std::ofstream(path, std::ios::binary)
          .write(reinterpret_cast<const char*>(texels.pixels.data()),
                 static_cast<std::streamsize>(texels.pixels.size()));
    };
    RunDirWriter writer(run->player(), dir, options);
    run->runToEnd();
    writer.finish();
    EXPECT_EQ(readText(dir / "hashes.txt"), readText(base / "0" / "hashes.txt")) << queue;
  }
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(base / "0" / "frames")) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(readText(base / "1" / "frames" / name), readText(e.path())) << name;
    EXPECT_EQ(readText(base / "8" / "frames" / name), readText(e.path())) << name;
    ++files;
  }
  EXPECT_EQ(files, 2 * ((180 + 29) / 30));
  std::filesystem::remove_all(base);
}

// A picture that cannot be written stops the run with the writer's error, whichever thread wrote it.
TEST(RunDir, APictureThatCannotBeWrittenStopsTheRun) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vbim-run-dir-failure-" + std::to_string(::getpid()));
  for (const std::size_t queue : {std::size_t{0}, std::size_t{8}}) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    auto run = Scenario::bareFile(testing::samplePath("day_clear.vbim")).seed(3).start(fromMs(3'000));
    RunDirOptions options;
    options.every = 60;
    options.trace = false;
    options.pictureQueue = queue;
    options.writeImage = [](const std::filesystem::path& path, Rgba8Image&) {
      if (path.filename() == "sky_000120.png") throw Error(path.string() + ": cannot write the PNG: disk full");
    };
    RunDirWriter writer(run->player(), dir, options);
    try {
      run->runToEnd();
      writer.finish();
      ADD_FAILURE() << "no error with queue " << queue;
    } catch (const std::exception& e) {
      // From inside the simulation (the sink, or the next picture after a failed one on the thread)
      // the scheduler names its process before the writer's message; from finish(), the message alone.
      EXPECT_TRUE(std::string(e.what()).ends_with((dir / "frames" / "sky_000120.png").string() +
                                                  ": cannot write the PNG: disk full"))
          << queue << ": " << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vbim::player
