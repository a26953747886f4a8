// Golden hash lists: for each sample stream and fault plan, the vsyncs at which the output changed and
// its 64-bit hash (docs/player.md "hashes.txt") are committed in tests/player/golden/ and compared.
// The test never rewrites them on its own: after a deliberate change of the model or the samples,
// regenerate with scripts/update-golden.sh (it sets VBIM_UPDATE_GOLDEN=1, which writes the lists
// and skips the comparison), review the diff, commit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/fault_plan_toml.hpp"
#include "player/frame_hash.hpp"
#include "player/scenario.hpp"
#include "tests/player/sample_path.hpp"
#include "tests/support/golden_file.hpp"

namespace vbim::player {
namespace {

struct Case {
  const char* name;
  const char* sample;
  const char* faults;  // fault plan TOML (LBAs: the bare file starts at 2048)
  Tick duration;
  int branchVariant;  // -1: none; else branch at 6 s
};

const Case kCases[] = {
    {"clear_none", "day_clear.vbim", "", fromMs(8'000), -1},
    {"clear_long_stall", "day_clear.vbim", "[[fault]]\nkind='stall'\nat='200ms'\nduration='5s'\n", fromMs(9'000), -1},
    {"clear_read_errors", "day_clear.vbim",
     "[[fault]]\nkind='read_error'\nlba=2050\nattempts=400\n[[fault]]\nkind='read_error'\nlba=2100\nattempts=3\n",
     fromMs(8'000), -1},
    {"clear_seek_away", "day_clear.vbim", "[[fault]]\nkind='seek_away'\nat='400ms'\nlba=3000\nsectors=100\n",
     fromMs(8'000), -1},
    {"clear_loop_wrap", "day_clear.vbim", "", fromMs(51'000), -1},
    {"weather_none", "day_weather.vbim", "", fromMs(8'000), -1},
    {"weather_long_stall", "day_weather.vbim", "[[fault]]\nkind='stall'\nat='200ms'\nduration='5s'\n", fromMs(9'000),
     -1},
    {"weather_read_errors", "day_weather.vbim", "[[fault]]\nkind='read_error'\nlba=2060\nattempts=400\n", fromMs(8'000),
     -1},
    {"weather_seek_away", "day_weather.vbim", "[[fault]]\nkind='seek_away'\nat='400ms'\nlba=3000\nsectors=100\n",
     fromMs(8'000), -1},
    {"weather_loop_wrap", "day_weather.vbim", "", fromMs(50'000), -1},
    {"weather_branch", "day_weather.vbim", "", fromMs(12'000), 1},
};

std::string goldenPath(const Case& c) {
  return testing::sourceDir() + "/tests/player/golden/" + c.name + ".txt";
}

// "vsync hash" for vsync 0 and every vsync whose hash differs from the one before.
std::string hashList(const Case& c) {
  Scenario sc = Scenario::bareFile(testing::samplePath(c.sample)).seed(1).trace(false);
  if (*c.faults != 0) sc.faults(config::parseFaultPlan(c.faults, "<scenario faults>", &sc.disc()));
  if (c.branchVariant >= 0) sc.branch(fromMs(6'000), c.branchVariant);
  auto run = sc.start(c.duration);
  run->runToEnd();
  std::ostringstream s;
  std::uint64_t prev = 0;
  for (const VsyncRow& r : run->rows()) {
    if (r.vsync == 0 || r.hash != prev) s << r.vsync << " " << hashHex(r.hash) << "\n";
    prev = r.hash;
  }
  return s.str();
}

class Golden : public ::testing::TestWithParam<Case> {};

TEST_P(Golden, HashListMatchesTheCommittedOne) {
  const Case& c = GetParam();
  const std::string got = hashList(c);
  vbim::testing::expectMatchesGolden(got, goldenPath(c), std::string(c.name) + ": the hash list");
}

INSTANTIATE_TEST_SUITE_P(Samples, Golden, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace vbim::player
