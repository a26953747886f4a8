// A fault-plan test: the plan is TOML (docs/fault-plans.md), read by config::parseFaultPlan. A
// scratched sector that defeats the drive's own retries, then another client taking the drive away:
// the stream ring absorbs both, and the lightmap never leaves the fault-free run. Needs the model and
// the configuration layer (vbim::testing).
#include <gtest/gtest.h>

#include <string>

#include "config/fault_plan_toml.hpp"
#include "player/scenario.hpp"

using namespace vbim;

// VBIM_SAMPLES_DIR comes from CMakeLists.txt: the sample streams installed with vbim.
const std::string kClearDay = std::string(VBIM_SAMPLES_DIR) + "/day_clear.vbim";

// LBAs are disc sectors: Scenario::bareFile puts the stream file at player::kBareFileLba (2048).
constexpr const char* kPlan = R"(
[[fault]]
kind = "read_error"
lba = 2100
attempts = 400      # more than the 257 attempts of one drive command: error 0x30

[[fault]]
kind = "seek_away"
at = "3s"
lba = 3000
sectors = 100
)";

TEST(FaultPlanTest, ReadErrorAndSeekAwayAreAbsorbedByTheRing) {
  auto scenario = player::Scenario::bareFile(kClearDay).seed(7);
  // The disc resolves `file = "..."` entries and bounds-checks the LBAs.
  scenario.faults(config::parseFaultPlan(kPlan, "read-error-and-seek-away.toml", &scenario.disc()));
  auto run = scenario.start(fromMs(12'000));
  run->runToEnd();

  const player::Pipeline& pipeline = run->player().pipeline();
  // The drive retried the scratched sector until its command gave up with an error; the ring
  // reported it to the EE once, then read the sector again.
  EXPECT_GE(pipeline.drive().stats().retries, 257);
  EXPECT_EQ(pipeline.ring().stats().errors, 1);
  EXPECT_EQ(pipeline.demux().counters().readErrors, 1);
  // The other client had the drive when the ring wanted it.
  EXPECT_GE(pipeline.ring().stats().issueFailures, 1);
  // The banks already read covered both: no frame lost or late, no difference from the
  // fault-free reference run at any vsync.
  EXPECT_EQ(pipeline.demux().counters().framesLost, 0);
  EXPECT_EQ(run->counters().framesLate, 0);
  EXPECT_EQ(run->totals().lag.value, 0);
}
