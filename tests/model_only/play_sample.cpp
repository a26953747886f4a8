// The model on its own, without GoogleTest: plays a stream file for a number of simulated seconds
// through player::Scenario (seed 1, no faults) and prints the hash of the last vsync, as
// hashes.txt writes it (docs/player.md). With a third argument it fails unless the hash is that one.
//
//   model_only_play_sample STREAM SECONDS [EXPECTED_HASH]
//
// scripts/check-model.sh builds it with no third-party header reachable and checks that it links
// nothing but the C and C++ runtime.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "player/frame_hash.hpp"
#include "player/scenario.hpp"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: %s STREAM SECONDS [EXPECTED_HASH]\n", argv[0]);
    return 2;
  }
  try {
    using namespace vbim;
    const Tick duration = fromMs(std::atoll(argv[2]) * 1'000);
    auto run = player::Scenario::bareFile(argv[1]).seed(1).trace(false).start(duration);
    run->runToEnd();
    const std::string hash = player::hashHex(run->lastRow().hash);
    std::printf("vsync %lld hash %s\n", static_cast<long long>(run->lastRow().vsync), hash.c_str());
    if (argc == 4 && hash != argv[3]) {
      std::fprintf(stderr, "expected hash %s\n", argv[3]);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
