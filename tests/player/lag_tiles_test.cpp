// The player's lag compares only the tiles either lightmap changed (gs::TiledDifference): at every
// vsync of fault plays it must equal the whole-image comparison of the run's and the reference's
// lightmap and sky, with the SIMD and the scalar kernels, with and without the blender's
// convergence shortcut, in full and strip upload modes.
#include <gtest/gtest.h>

#include "config/fault_plan_toml.hpp"
#include "gs/lag_meter.hpp"
#include "gs/simd/blend_simd.hpp"
#include "player/scenario.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::player {
namespace {

constexpr const char* kFaults =
    "[[fault]]\nkind='stall'\nat='200ms'\nduration='4s'\n"
    "[[fault]]\nkind='random_stall'\nfrom='0s'\nduration='40s'\nmean_interval='6s'\nstall='3s'\n";

void checkEveryVsync(const char* sample, bool simdKernels, bool aware, bool strips) {
  Scenario sc = Scenario::bareFile(testing::samplePath(sample)).seed(2).trace(false);
  if (simdKernels) sc.kernels(Kernels{&gs::simd::kernels(), nullptr, nullptr});
  sc.options().config.gs.convergence_aware = aware;
  if (strips) sc.options().config.gs.upload_mode = "strips";
  sc.faults(config::parseFaultPlan(kFaults, "<faults>", &sc.disc()));
  auto run = sc.start(fromMs(40'000));
  Player& p = run->player();
  ASSERT_TRUE(p.hasReference());
  const Player::Sink inner = p.sink();
  int differing = 0;
  int vsyncs = 0;
  p.setSink([&](const VsyncRow& row, const Rgba8Image& lightmap, const Rgba8Image* sky) {
    inner(row, lightmap, sky);
    ++vsyncs;
    const gs::LagSample lm = gs::compareImages(lightmap, p.reference()->lightmap().lightmap());
    ASSERT_EQ(row.lag, lm.maxDiff) << "vsync " << row.vsync;
    ASSERT_NE(sky, nullptr);
    const gs::LagSample s = gs::compareImages(*sky, p.reference()->sky()->lightmap());
    ASSERT_EQ(row.skyLag, s.maxDiff) << "vsync " << row.vsync;
    if (lm.maxDiff != 0) ++differing;
  });
  run->runToEnd();
  EXPECT_EQ(vsyncs, static_cast<int>(run->rows().size()));
  EXPECT_GT(differing, 100) << "the faults should make the run differ from the reference";
}

TEST(LagTiles, EqualsTheWholeImageComparisonSimd) {
  checkEveryVsync("day_clear.vbim", true, true, false);
}
TEST(LagTiles, EqualsTheWholeImageComparisonScalarWithoutShortcut) {
  checkEveryVsync("day_weather.vbim", false, false, false);
}
TEST(LagTiles, EqualsTheWholeImageComparisonInStrips) {
  checkEveryVsync("day_clear.vbim", true, true, true);
}

}  // namespace
}  // namespace vbim::player
