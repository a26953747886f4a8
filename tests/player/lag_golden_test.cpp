// Golden lag lists: for fault plays of the sample streams, the lightmap and sky lag (the largest
// per-byte difference from the fault-free reference run, docs/player.md "timeline.csv") at vsync 0
// and at every vsync where either changed, committed in tests/player/golden/lag/ and compared. They
// pin the comparison with the reference: any shortcut in it (SIMD, comparing only changed tiles)
// must give the same numbers at every vsync. Regenerate only after a deliberate change of the model
// or the samples: scripts/update-golden.sh (VBIM_UPDATE_GOLDEN=1), review the diff, commit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/fault_plan_toml.hpp"
#include "player/scenario.hpp"
#include "tests/player/sample_path.hpp"
#include "tests/support/golden_file.hpp"

namespace vbim::player {
namespace {

struct LagCase {
  const char* name;
  const char* sample;
  const char* faults;  // fault plan TOML (LBAs: the bare file starts at 2048)
  Tick duration;
  const char* policy;
  bool convergenceAware;
  int catchupFix;
  int branchVariant;  // -1: none; else branch at 20 s
};

// A stall, a read error and random stalls, as bench/player/fault-plan.toml, over a shorter play.
constexpr const char* kMixed =
    "[[fault]]\nkind='stall'\nat='200ms'\nduration='6s'\n"
    "[[fault]]\nkind='read_error'\nlba=2090\nattempts=300\n"
    "[[fault]]\nkind='random_stall'\nfrom='0s'\nduration='90s'\nmean_interval='8s'\nstall='3s'\n";

const LagCase kCases[] = {
    {"clear_long_stall", "day_clear.vbim", "[[fault]]\nkind='stall'\nat='200ms'\nduration='5s'\n", fromMs(12'000),
     "blend-through", true, 0, -1},
    {"clear_loop_stall", "day_clear.vbim", "[[fault]]\nkind='stall'\nat='20s'\nduration='10s'\n", fromMs(45'000),
     "blend-through", true, 0, -1},
    {"clear_mixed", "day_clear.vbim", kMixed, fromMs(90'000), "blend-through", true, 0, -1},
    {"clear_mixed_hard_skip_unaware", "day_clear.vbim", kMixed, fromMs(60'000), "hard-skip", false, 0, -1},
    {"clear_mixed_play_late_catchup", "day_clear.vbim", kMixed, fromMs(60'000), "play-late", true, 96, -1},
    {"weather_mixed_branch", "day_weather.vbim", kMixed, fromMs(60'000), "blend-through", true, 0, 1},
    {"weather_read_errors", "day_weather.vbim", "[[fault]]\nkind='read_error'\nlba=2060\nattempts=400\n",
     fromMs(10'000), "blend-through", true, 0, -1},
};

void PrintTo(const LagCase& c, std::ostream* os) {
  *os << c.name;
}

std::string goldenPath(const LagCase& c) {
  return testing::sourceDir() + "/tests/player/golden/lag/" + c.name + ".txt";
}

// "vsync lag skyLag" for vsync 0 and every vsync where either differs from the row before.
std::string lagList(const LagCase& c) {
  Scenario sc = Scenario::bareFile(testing::samplePath(c.sample)).seed(3).trace(false).policy(c.policy);
  sc.options().config.gs.convergence_aware = c.convergenceAware;
  sc.options().config.gs.catchup_fix = c.catchupFix;
  sc.faults(config::parseFaultPlan(c.faults, "<lag case faults>", &sc.disc()));
  if (c.branchVariant >= 0) sc.branch(fromMs(20'000), c.branchVariant);
  auto run = sc.start(c.duration);
  run->runToEnd();
  EXPECT_TRUE(run->player().hasReference());
  std::ostringstream s;
  const VsyncRow* prev = nullptr;
  for (const VsyncRow& r : run->rows()) {
    if (prev == nullptr || r.lag != prev->lag || r.skyLag != prev->skyLag)
      s << r.vsync << " " << r.lag << " " << r.skyLag << "\n";
    prev = &r;
  }
  return s.str();
}

class LagGolden : public ::testing::TestWithParam<LagCase> {};

TEST_P(LagGolden, LagListMatchesTheCommittedOne) {
  const LagCase& c = GetParam();
  const std::string got = lagList(c);
  vbim::testing::expectMatchesGolden(got, goldenPath(c), std::string(c.name) + ": the lag list");
}

INSTANTIATE_TEST_SUITE_P(Samples, LagGolden, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<LagCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace vbim::player
