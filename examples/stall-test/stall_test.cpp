// A stall-injection test: the drive freezes for 6 s while the stream starts; the lightmap falls
// behind during the stall and catches up smoothly afterwards. Needs the model only (vbim::model).
#include <gtest/gtest.h>

#include <string>

#include "player/scenario.hpp"

using namespace vbim;

// VBIM_SAMPLES_DIR comes from CMakeLists.txt: the sample streams installed with vbim.
const std::string kClearDay = std::string(VBIM_SAMPLES_DIR) + "/day_clear.vbim";

TEST(StallTest, FallsBehindDuringADriveStallThenCatchesUp) {
  // The disc: a bare stream file; the stall: the drive freezes for 6 s during the spin-up.
  auto run = player::Scenario::bareFile(kClearDay)
                 .seed(42)
                 .stall(fromMs(200), fromMs(6'000))
                 .start(fromMs(12'000));  // vsyncs up to 12 s of simulated time

  // During the stall no frame arrives: the presenter is behind schedule.
  run->runTo(fromMs(5'000));
  EXPECT_TRUE(run->lastRow().lightmap.behind);
  EXPECT_GT(run->lastRow().lag, 0);  // against the fault-free reference run beside it

  // After it, the late frames are blended toward (catch-up frames), not copied in...
  run->runToEnd();
  const gs::PresenterCounters& c = run->counters();
  EXPECT_GT(c.framesLate, 0);
  EXPECT_GT(c.framesCaughtUp, 0);
  EXPECT_EQ(c.snaps, 1);  // one snap: the very first frame, copied into the empty lightmap
  // ...and the lightmap is back on the stall-free run, within the blend's rounding band.
  EXPECT_FALSE(run->lastRow().lightmap.behind);
  EXPECT_LE(run->lastRow().lag, 1);
  // The hashes of every vsync are there for golden comparisons.
  EXPECT_EQ(run->hashes().size(), run->rows().size());
}
