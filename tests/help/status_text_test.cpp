// help/status_text: the progress line's bar, count, rate and time left, profile's shorter counts and
// --verbose's file sizes.
#include "help/status_text.hpp"

#include <gtest/gtest.h>

namespace {

using namespace vbim::help;

TEST(StatusText, TheLineHasTheBarTheCountTheRateAndTheTimeLeft) {
  // Half done after 4 s: 30 marks, 15 filled; 2 frames/s leaves 8 s for 16 more.
  EXPECT_EQ(progressLine("vbim lightmap", "frames", 16, 32, 8.0, "clear 3"),
            "vbim lightmap [###############...............] 16/32 frames  2 frames/s, 8 s left  clear 3");
  // Not yet half a second: no rate. Done: no time left.
  EXPECT_EQ(progressLine("vbim play", "s", 0.5, 60, 0.2, ""), "vbim play [..............................] 0.5/60 s");
  EXPECT_EQ(progressLine("vbim play", "s", 60, 60, 10, ""),
            "vbim play [##############################] 60/60 s  6 s/s");
  // A total not known in advance: the count alone.
  EXPECT_EQ(progressLine("vbim decode", "pictures", 7, 0, 0, ""), "vbim decode 7 pictures");
}

TEST(StatusText, DurationsAndClocks) {
  EXPECT_EQ(durationText(8.4), "8 s");
  EXPECT_EQ(durationText(200), "3 min 20 s");
  EXPECT_EQ(durationText(3900), "1 h 05 min");
  EXPECT_EQ(clockText(200), "3m20s");
  EXPECT_EQ(clockText(3900), "1h05m");
}

TEST(StatusText, SecondsLeftAndTheCount) {
  EXPECT_DOUBLE_EQ(secondsLeft(10, 2, 6), 20);
  EXPECT_DOUBLE_EQ(secondsLeft(10, 0, 6), 0);
  EXPECT_DOUBLE_EQ(secondsLeft(10, 8, 6), 0);  // more done than planned: nothing left, not a wrap
  EXPECT_EQ(countText(3, 10, 4.6), "[3/10, 5 s left] ");
}

TEST(StatusText, SizesInDecimalUnits) {
  EXPECT_EQ(sizeText(812), "812 bytes");
  EXPECT_EQ(sizeText(12345), "12.3 kB");
  EXPECT_EQ(sizeText(4'500'000), "4.5 MB");
}

}  // namespace
