// The run directory through the test API: the files `vbim play` writes, from a Scenario's run, with
// the rows the Run records still there (the writer chains after the Run's own sink).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "player/fault_spans.hpp"
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

// faults.csv says when the drive was disturbed: the plan's stall as planned, and the read error
// when the drive met it (the plan gives only its sector), read back as written (issue #33).
TEST(RunDir, FaultsCsvHasThePlannedStallAndTheReadErrorAsMet) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vbim-run-dir-faults-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run = Scenario::bareFile(testing::samplePath("day_clear.vbim"))
                 .stall(fromMs(200), fromMs(1'000))
                 .readError(42, 300)
                 .start(fromMs(8'000));
  RunDirOptions options;
  options.trace = false;
  RunDirWriter writer(run->player(), dir, options);
  run->runToEnd();
  writer.finish();
  const std::vector<FaultSpan> spans = readFaultSpansCsv(dir / "faults.csv");
  // The stall, then the read error as the drive met it: its retries, and after a failed read the
  // driver's retries of the read (one or more runs of vsyncs), once the stall was over.
  ASSERT_GE(spans.size(), 2u) << readText(dir / "faults.csv");
  EXPECT_EQ(spans[0], (FaultSpan{"stall", 0.2, 1.2}));
  for (std::size_t i = 1; i < spans.size(); ++i) {
    EXPECT_EQ(spans[i].kind, "read error") << i;
    EXPECT_GT(spans[i].endS, spans[i].beginS) << i;
    EXPECT_GE(spans[i].beginS, 1.2) << i;
    EXPECT_LT(spans[i].endS, 8.0) << i;
  }
  EXPECT_TRUE(readText(dir / "faults.csv").starts_with("kind,begin_s,end_s\nstall,0.200000,1.200000\n"));
  std::filesystem::remove_all(dir);
}

TEST(FaultSpans, ReadErrorsAreTheVsyncsAtWhichTheRetriesGrew) {
  ReadErrorSpans r;
  const Tick v = kBusHz / 60;
  const std::int64_t retries[] = {0, 0, 3, 5, 5, 5, 6, 6};
  for (int i = 0; i < 8; ++i) r.onVsync(i * v, retries[i]);
  const std::vector<FaultSpan> s = r.spans();
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], (FaultSpan{"read error", toSeconds(1 * v), toSeconds(3 * v)}));
  EXPECT_EQ(s[1], (FaultSpan{"read error", toSeconds(5 * v), toSeconds(6 * v)}));
}

TEST(FaultSpans, ThePlansTimedEntriesClippedToTheRun) {
  iop::FaultPlan plan;
  iop::Fault stall;
  stall.at = fromMs(9'000);
  stall.duration = fromMs(5'000);
  iop::Fault contention;
  contention.kind = iop::Fault::Kind::Contention;
  contention.at = fromMs(1'000);
  contention.duration = fromMs(2'000);
  iop::Fault error;
  error.kind = iop::Fault::Kind::ReadError;
  plan.faults = {stall, contention, error};
  const std::vector<FaultSpan> s = mergeFaultSpans(plannedFaultSpans(plan, fromMs(10'000)), {});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], (FaultSpan{"contention", 1.0, 3.0}));
  EXPECT_EQ(s[1], (FaultSpan{"stall", 9.0, 10.0}));
}

TEST(FaultSpans, AMalformedRowNamesTheFileAndLine) {
  const std::filesystem::path f =
      std::filesystem::temp_directory_path() / ("vbim-faults-csv-" + std::to_string(::getpid()) + ".csv");
  std::ofstream(f) << "kind,begin_s,end_s\nstall,1,2\nstall,x\n";
  try {
    readFaultSpansCsv(f);
    FAIL() << "expected vbim::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(f.string() + ":3: expected kind,begin_s,end_s"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(f);
  EXPECT_TRUE(readFaultSpansCsv(f).empty()) << "no file: no faults";
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
