// Peak memory of playback (issue #7 item 9), measured on child processes (ru_maxrss from wait4):
//   - independent of the stream's length: `vbim play --no-trace` on a long stream played to its end
//     peaks no higher than on a short one, within 3 MiB (the player streams sectors through the
//     ring, never loads a whole file, and its per-vsync rows go to files, not memory);
//   - the speed bench's case (512x512 lightmap + 256x128 sky, 59.94 Hz, 2 s per frame) under 64 MB
//     in the lean player process (player_memory_probe: the model alone). The `vbim` binary itself
//     starts at about 120 MB before playing anything: OpenImageIO's static ustring table (25 MB)
//     and the code pages of OIIO, OpenCV, FFmpeg and their dependencies; the test prints both.
// Under AddressSanitizer the absolute bound is skipped (shadow memory and quarantine inflate RSS).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "streams/authoring/bench_stream.hpp"

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
  const fs::path d = fs::path(::testing::TempDir()) / ("vbim_memory_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

void writeFile(const fs::path& p, const std::vector<std::uint8_t>& bytes) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Runs a program and returns its peak resident set in KiB (-1 if it failed).
long peakKiB(std::vector<std::string> args) {
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
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return ru.ru_maxrss;  // KiB on Linux
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
                    config_.string(), "--force", "--out", (dir_ / out).string()});
  }
  fs::path dir_, config_;
};

TEST_F(PlayerMemory, PeakDoesNotGrowWithTheStreamsLength) {
#ifdef VBIM_ASAN
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed pictures resident";
#endif
  // Noise frames: the largest pictures (about 200 KiB each), so a whole-file load would show.
  using vbim::bench::BenchContent;
  writeFile(dir_ / "short.vbim", vbim::bench::authorBenchStream(3, BenchContent::noise, 1));
  writeFile(dir_ / "long.vbim", vbim::bench::authorBenchStream(64, BenchContent::noise, 1));
  const auto longBytes = static_cast<long>(fs::file_size(dir_ / "long.vbim"));
  const auto shortBytes = static_cast<long>(fs::file_size(dir_ / "short.vbim"));
  ASSERT_GT(longBytes - shortBytes, 5L << 20) << "the long stream must be much longer for the test to mean anything";
  // Measured on the lean player (the model alone): the vbim binary adds ~125 MB of libraries and
  // OpenImageIO tables whose allocator noise (several MB between runs) would hide a file-sized change.
  const long shortPeak = peakKiB({PLAYER_PROBE, (dir_ / "short.vbim").string(), "30s", config_.string()});
  const long longPeak = peakKiB({PLAYER_PROBE, (dir_ / "long.vbim").string(), "128s", config_.string()});
  ASSERT_GT(shortPeak, 0) << "player_memory_probe failed on the short stream";
  ASSERT_GT(longPeak, 0) << "player_memory_probe failed on the long stream";
  // The CLI on the same two streams, reported for the record and required to succeed.
  const long shortCli = play(dir_ / "short.vbim", "30s", "out_short");
  const long longCli = play(dir_ / "long.vbim", "128s", "out_long");
  ASSERT_GT(shortCli, 0) << "vbim play failed on the short stream";
  ASSERT_GT(longCli, 0) << "vbim play failed on the long stream";
  std::cout << "peak RSS: short stream (" << shortBytes / 1024 << " KiB, 30 s, looping) player " << shortPeak
            << " KiB, vbim play " << shortCli << " KiB; long stream (" << longBytes / 1024 << " KiB, 128 s) player "
            << longPeak << " KiB, vbim play " << longCli << " KiB\n";
  // The long file is 5+ MiB longer and plays 4x as long; 3 MiB of slack (half the file) covers the buffers'
  // warm-up (picture vectors reach the largest picture's size) and allocator noise.
  EXPECT_LE(longPeak, shortPeak + 3072);
}

TEST_F(PlayerMemory, BenchCaseStaysUnder64MB) {
#ifdef VBIM_ASAN
  GTEST_SKIP() << "AddressSanitizer inflates the resident set";
#endif
  writeFile(dir_ / "bench.vbim", vbim::bench::authorBenchStream(24, vbim::bench::BenchContent::syntheticDay));
  const long peak = peakKiB({PLAYER_PROBE, (dir_ / "bench.vbim").string(), "60s", config_.string()});
  const long cli = play(dir_ / "bench.vbim", "60s", "out_bench");
  ASSERT_GT(peak, 0) << "player_memory_probe failed";
  ASSERT_GT(cli, 0) << "vbim play failed";
  std::cout << "peak RSS of the bench case, 60 s: player " << peak << " KiB; vbim play " << cli
            << " KiB (the binary's libraries included)\n";
  EXPECT_LT(peak, 64L * 1024);
}

}  // namespace
