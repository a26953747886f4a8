#include "runtime/serial_unit.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vbim {
namespace {

struct Use {
  std::string who;
  Tick from, to;
};

// A client that asks for the unit at `at`, holds it for `hold`, `times` times in a row.
Task<void> client(Scheduler& s, SerialUnit& unit, std::vector<Use>& log, std::string who, Tick at, Tick hold,
                  int times) {
  co_await s.until(at);
  for (int i = 0; i < times; ++i) {
    co_await unit.acquire();
    const Tick from = s.now();
    co_await s.delay(hold);
    log.push_back({who, from, s.now()});
    unit.release();
  }
}

TEST(SerialUnit, OneClientAtATimeInTheOrderTheyAsked) {
  Scheduler s;
  SerialUnit unit(s);
  std::vector<Use> log;
  s.spawn("a", client(s, unit, log, "a", 0, 10, 2));
  s.spawn("b", client(s, unit, log, "b", 0, 5, 1));
  s.spawn("c", client(s, unit, log, "c", 3, 1, 1));
  s.run();
  // a holds 0-10; b asked at 0, c at 3, a again at 10: b, c, then a.
  ASSERT_EQ(log.size(), 4u);
  EXPECT_EQ(log[0].who, "a");
  EXPECT_EQ(log[1].who, "b");
  EXPECT_EQ(log[1].from, 10);
  EXPECT_EQ(log[2].who, "c");
  EXPECT_EQ(log[2].from, 15);
  EXPECT_EQ(log[3].who, "a");
  EXPECT_EQ(log[3].from, 16);
  for (std::size_t i = 1; i < log.size(); ++i) EXPECT_GE(log[i].from, log[i - 1].to) << "overlap at " << i;
  // Waiting: b 10, c 12 (3 to 15), a's second request 6 (10 to 16).
  EXPECT_EQ(unit.waited(), 10 + 12 + 6);
  EXPECT_FALSE(unit.busy());
}

TEST(SerialUnit, AFreeUnitIsTakenAtOnce) {
  Scheduler s;
  SerialUnit unit(s);
  std::vector<Use> log;
  s.spawn("a", client(s, unit, log, "a", 7, 2, 3));
  s.run();
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[0].from, 7);
  EXPECT_EQ(log[2].to, 13);
  EXPECT_EQ(unit.waited(), 0);
}

}  // namespace
}  // namespace vbim
