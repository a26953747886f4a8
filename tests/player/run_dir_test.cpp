// The run directory through the test API: the files `vbim play` writes, from a Scenario's run, with
// the rows the Run records still there (the writer chains after the Run's own sink).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "player/report.hpp"
#include "player/run_dir.hpp"
#include "player/scenario.hpp"
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

}  // namespace
}  // namespace vbim::player
