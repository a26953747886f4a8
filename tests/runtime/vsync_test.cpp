#include "runtime/vsync.hpp"

#include <gtest/gtest.h>

namespace vbim {
namespace {

TEST(Vsync, NtscIsExactOver24Hours) {
  const VsyncClock v(kNtsc);
  const std::int64_t day = 24LL * 3600;
  // 24 h at 60000/1001 Hz = 86400 * 60000 / 1001 = 5,178,821.178... vsyncs.
  const std::int64_t expected = day * 60000 / 1001;
  EXPECT_EQ(v.countAt(day * kBusHz), expected);
  // The n-th vsync is floor(n * period), not n * rounded period.
  const std::int64_t n = expected;
  const __int128 exact = static_cast<__int128>(n) * kBusHz * 1001 / 60000;
  EXPECT_EQ(v.time(n), static_cast<Tick>(exact));
  // Adding a rounded period would drift: 2,460,058 * n differs by thousands of ticks.
  EXPECT_GT(2'460'058LL * n - v.time(n), 1000);
}

TEST(Vsync, AllRatesCountExactlyOverADay) {
  const std::int64_t day = 24LL * 3600;
  for (VsyncRate r : {kNtsc, kNtscProgressive, kPal, kPalProgressive}) {
    const VsyncClock v(r);
    const std::int64_t expected = day * r.num / r.den;  // floor
    EXPECT_EQ(v.countAt(day * kBusHz), expected) << r.name;
    // Spacing never varies by more than one tick.
    for (std::int64_t n = 0; n < 1000; ++n) {
      const Tick d = v.time(n + 1) - v.time(n);
      EXPECT_LE(d - kBusHz * r.den / r.num, 1) << r.name;
      EXPECT_GE(d, kBusHz * r.den / r.num) << r.name;
    }
  }
}

TEST(Vsync, PalPeriodIsExact) {
  const VsyncClock v(kPal);
  EXPECT_EQ(v.time(1), 2'949'120);  // 20 ms = 2,949,120 bus cycles (docs/hardware.md#clocks)
  EXPECT_EQ(v.time(50), kBusHz);
}

TEST(Vsync, CountAtBoundaries) {
  const VsyncClock v(kNtsc, 1000);
  EXPECT_EQ(v.countAt(999), -1);
  EXPECT_EQ(v.countAt(1000), 0);
  for (std::int64_t n = 1; n < 2000; n += 37) {
    EXPECT_EQ(v.countAt(v.time(n)), n);
    EXPECT_EQ(v.countAt(v.time(n) - 1), n - 1);
  }
}

TEST(Vsync, RateByName) {
  VsyncRate r{};
  ASSERT_TRUE(vsyncRateByName("pal-p", r));
  EXPECT_EQ(r.num, 4976);
  EXPECT_FALSE(vsyncRateByName("secam", r));
}

}  // namespace
}  // namespace vbim
