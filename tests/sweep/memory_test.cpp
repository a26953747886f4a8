// Peak memory of playback (issue #7 item 9), measured on child processes (ru_maxrss from wait4):
//   - independent of the stream's length: `vbim play --no-trace` on a long stream played to its end
//     peaks no higher than on a short one, within 3 MiB (the player streams sectors through the
//     ring, never loads a whole file, and its per-vsync rows go to files, not memory);
//   - independent of the run's length with tracing on (the default): trace.json and signals.vcd are
//     written as the run goes (issue #16: 370 MB at 600 s, 2 GB at 1 h when they were kept);
//   - the speed bench's case (512x512 lightmap + 256x128 sky, 59.94 Hz, 2 s per frame) under 64 MB
//     for `vbim play` as the user runs it, the program's libraries included (`vbim` links the model
//     and small libraries only; OpenImageIO, FFmpeg and Mesa live in vbim-full, cli/command.hpp).
// Under AddressSanitizer the absolute bound is skipped (shadow memory and quarantine inflate RSS).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "streams/authoring/bench_stream.hpp"
#include "tests/support/scratch.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define VBIM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VBIM_ASAN 1
#endif
#endif

namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  return vbim::testing::scratchDir("memory");
}

void writeFile(const fs::path& p, const std::vector<std::uint8_t>& bytes) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Runs a program through peak_rss (see peak_rss.cpp) and returns its peak resident set in KiB
// (-1 if it failed).
long peakKiB(std::vector<std::string> args, const fs::path& scratchDir) {
  const fs::path report = scratchDir / "peak_rss.txt";
  fs::remove(report);
  args.insert(args.begin(), {PEAK_RSS, report.string()});
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (!freopen("/dev/null", "w", stdout)) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  long kib = -1;
  std::ifstream(report) >> kib;
  return kib;
}

class PlayerMemory : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch();
    config_ = dir_ / "bench.toml";
    std::ofstream(config_) << "gs.upload_mode = \"strips\"\ngs.sky_height = 128\n";
  }
  void TearDown() override {
    if (std::getenv("VBIM_KEEP_MEMORY_TEST_FILES") == nullptr) fs::remove_all(dir_);  // set it to look at the streams
  }
  long play(const fs::path& stream, const std::string& duration, const std::string& out) const {
    return peakKiB({VBIM_CLI, "play", stream.string(), "--no-trace", "--duration", duration, "--config",
                    config_.string(), "--force", "--out", (dir_ / out).string()},
                   dir_);
  }
  fs::path dir_, config_;
};

TEST_F(PlayerMemory, PeakDoesNotGrowWithTheStreamsLength) {
#ifdef VBIM_ASAN
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed pictures resident";
#endif
  // Noise frames: the largest pictures (about 200 KiB each), so a whole-file load would show.
  using vbim::streams::BenchContent;
  writeFile(dir_ / "short.vbim", vbim::streams::authorBenchStream(3, BenchContent::Noise, 1));
  writeFile(dir_ / "long.vbim", vbim::streams::authorBenchStream(64, BenchContent::Noise, 1));
  const auto longBytes = static_cast<long>(fs::file_size(dir_ / "long.vbim"));
  const auto shortBytes = static_cast<long>(fs::file_size(dir_ / "short.vbim"));
  ASSERT_GT(longBytes - shortBytes, 5L << 20) << "the long stream must be much longer for the test to mean anything";
  const long shortPeak = play(dir_ / "short.vbim", "30s", "out_short");
  const long longPeak = play(dir_ / "long.vbim", "128s", "out_long");
  ASSERT_GT(shortPeak, 0) << "vbim play failed on the short stream";
  ASSERT_GT(longPeak, 0) << "vbim play failed on the long stream";
  std::cout << "peak RSS of vbim play: short stream (" << shortBytes / 1024 << " KiB, 30 s, looping) " << shortPeak
            << " KiB; long stream (" << longBytes / 1024 << " KiB, 128 s) " << longPeak << " KiB\n";
  // The long file is 5+ MiB longer and plays 4x as long; 1.5 MiB of slack covers the buffers'
  // warm-up (picture vectors reach the largest picture's size) and allocator noise (measured: the
  // two peaks differ by ~0.2 MiB).
  EXPECT_LE(longPeak, shortPeak + 1536);
}

TEST_F(PlayerMemory, BenchCaseStaysUnder64MB) {
#ifdef VBIM_ASAN
  GTEST_SKIP() << "AddressSanitizer inflates the resident set";
#endif
  writeFile(dir_ / "bench.vbim", vbim::streams::authorBenchStream(24, vbim::streams::BenchContent::SyntheticDay));
  const long peak = play(dir_ / "bench.vbim", "60s", "out_bench");
  ASSERT_GT(peak, 0) << "vbim play failed";
  std::cout << "peak RSS of vbim play on the bench case, 60 s: " << peak << " KiB\n";
  EXPECT_LT(peak, 64L * 1024);
}

TEST_F(PlayerMemory, PeakDoesNotGrowWithTheRunsLengthWithTracing) {
#ifdef VBIM_ASAN
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed records resident";
#endif
  const auto traced = [&](const std::string& duration, const std::string& out) {
    return peakKiB({VBIM_CLI, "play", VBIM_SAMPLE, "--duration", duration, "--force", "--out", (dir_ / out).string()},
                   dir_);
  };
  const long shortPeak = traced("60s", "traced_short");
  const long longPeak = traced("900s", "traced_long");
  ASSERT_GT(shortPeak, 0) << "vbim play failed";
  ASSERT_GT(longPeak, 0) << "vbim play failed";
  const auto traceBytes = static_cast<long>(fs::file_size(dir_ / "traced_long" / "trace.json"));
  std::cout << "peak RSS of vbim play with tracing: 60 s " << shortPeak << " KiB, 900 s " << longPeak
            << " KiB (trace.json " << traceBytes / 1024 << " KiB)\n";
  ASSERT_GT(traceBytes, 8L << 20) << "the long run's trace must dwarf the slack for the test to mean anything";
  EXPECT_LE(longPeak, shortPeak + 2048);
}

}  // namespace
