#include "runtime/clock.hpp"

#include <gtest/gtest.h>

namespace vbim {
namespace {

TEST(Clock, ExactRatios) {
  EXPECT_EQ(fromMs(1), 147'456);
  EXPECT_EQ(fromIopCycles(36'864'000), kBusHz);  // one second of IOP cycles
  EXPECT_EQ(toIopCycles(kBusHz), kIopHz);
  EXPECT_EQ(toEeCycles(kBusHz), kEeHz);
  EXPECT_EQ(fromEeCycles(kEeHz), kBusHz);
  EXPECT_EQ(fromSecondsRational(1, 1), kBusHz);
  EXPECT_EQ(fromSecondsRational(1001, 60000), 2'460'058);  // 2,460,057.6 rounds up
  // IOP "1 ms" alarm of cdvdstm: 0x9000 IOP cycles = exactly 1 ms.
  EXPECT_EQ(fromIopCycles(0x9000), fromMs(1));
  // The 8 ms re-poll alarm 0x48000 IOP cycles.
  EXPECT_EQ(fromIopCycles(0x48000), fromMs(8));
}

TEST(Clock, RoundTripsWhereExact) {
  for (std::int64_t iop : {0LL, 1LL, 7LL, 36'864LL, 552'960'000LL}) EXPECT_EQ(toIopCycles(fromIopCycles(iop)), iop);
  for (Tick t : {0LL, 2LL, 1000LL, 147'456LL}) EXPECT_EQ(fromEeCycles(toEeCycles(t)), t);
  EXPECT_EQ(toIopCycles(5), 1);    // floor
  EXPECT_EQ(toIopCycles(-1), -1);  // floor, not truncation
  EXPECT_EQ(fromEeCycles(3), 2);   // 1.5 ticks occupy 2
}

TEST(Clock, MicrosAndSeconds) {
  EXPECT_EQ(fromUs(1000), fromMs(1));
  EXPECT_EQ(fromUs(1), 147);         // 147.456
  EXPECT_EQ(fromUs(3), 442);         // 442.368
  EXPECT_EQ(fromNs(13'900), 2'050);  // 2049.6384
  EXPECT_EQ(fromSeconds(12.5), 12 * kBusHz + kBusHz / 2);
  EXPECT_DOUBLE_EQ(toSeconds(kBusHz * 3), 3.0);
}

TEST(Clock, FormatMicrosIsIntegerExact) {
  char buf[32];
  formatMicros(kBusHz, buf, sizeof buf);
  EXPECT_STREQ(buf, "1000000.000");
  formatMicros(147, buf, sizeof buf);
  EXPECT_STREQ(buf, "0.997");  // 996.9 ns
  formatMicros(0, buf, sizeof buf);
  EXPECT_STREQ(buf, "0.000");
  formatMicros(-147'456, buf, sizeof buf);
  EXPECT_STREQ(buf, "-1000.000");
}

}  // namespace
}  // namespace vbim
