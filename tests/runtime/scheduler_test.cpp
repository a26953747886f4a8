#include "runtime/scheduler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/event.hpp"

namespace vbim {
namespace {

struct Log {
  Scheduler& s;
  std::vector<std::string> lines;
  void add(const std::string& what, const char* suffix = "") {
    std::ostringstream line;
    line << s.now() << ' ' << what << suffix;
    lines.push_back(line.str());
  }
};

Task<void> sleeper(Log& log, std::string name, Tick d, int times) {
  for (int i = 0; i < times; ++i) {
    co_await log.s.delay(d);
    log.add(name);
  }
}

TEST(Scheduler, OrdersByTimeThenInsertion) {
  Scheduler s;
  Log log{s, {}};
  s.spawn("a", sleeper(log, "a", 10, 3));
  s.spawn("b", sleeper(log, "b", 10, 3));
  s.spawn("c", sleeper(log, "c", 15, 2));
  s.run();
  // At 30, c runs first: it scheduled that wake-up at 15, before a and b scheduled theirs at 20.
  const std::vector<std::string> expected = {"10 a", "10 b", "15 c", "20 a", "20 b", "30 c", "30 a", "30 b"};
  EXPECT_EQ(log.lines, expected);
  EXPECT_EQ(s.now(), 30);
}

Task<void> zeroYield(Log& log, std::string name) {
  log.add(name, "1");
  co_await log.s.delay(0);
  log.add(name, "2");
}

TEST(Scheduler, ZeroDelayYieldsToEverythingDueNow) {
  Scheduler s;
  Log log{s, {}};
  s.spawn("x", zeroYield(log, "x"));
  s.spawn("y", zeroYield(log, "y"));
  s.run();
  const std::vector<std::string> expected = {"0 x1", "0 y1", "0 x2", "0 y2"};
  EXPECT_EQ(log.lines, expected);
}

Task<int> addLater(Scheduler& s, int a, int b) {
  co_await s.delay(5);
  co_return a + b;
}

Task<void> caller(Scheduler& s, int& out) {
  const int x = co_await addLater(s, 1, 2);
  const int y = co_await addLater(s, x, 10);
  out = y;
}

TEST(Scheduler, NestedTasksReturnValues) {
  Scheduler s;
  int out = 0;
  s.spawn("caller", caller(s, out));
  s.run();
  EXPECT_EQ(out, 13);
  EXPECT_EQ(s.now(), 10);
}

// The host stack address of the caller's frame: coroutine locals live on the heap, so the depth of
// the host stack is read from a plain function's frame.
[[gnu::noinline]] std::uintptr_t hostStackHere() {
  return reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
}

struct StackSpread {
  std::uintptr_t low = UINTPTR_MAX;
  std::uintptr_t high = 0;
  void note() {
    const std::uintptr_t at = hostStackHere();
    low = std::min(low, at);
    high = std::max(high, at);
  }
};

Task<void> oneTick(Scheduler& s, StackSpread& spread) {
  co_await s.delay(1);
  spread.note();
}

Task<void> manyNestedTicks(Scheduler& s, StackSpread& spread, int times) {
  for (int i = 0; i < times; ++i) co_await oneTick(s, spread);
}

// A process alone in the queue continues inline at each delay; each nested Task it finishes resumes
// its awaiter by symmetric transfer, which GCC does not compile as a tail call under ASan. The
// scheduler bounds the inline run, so the host stack stays shallow however long the loop runs.
TEST(Scheduler, InlineContinuationsDoNotGrowTheHostStack) {
  Scheduler s;
  StackSpread spread;
  constexpr int kTimes = 200'000;
  s.spawn("loop", manyNestedTicks(s, spread, kTimes));
  s.run();
  EXPECT_EQ(s.now(), kTimes);
  EXPECT_LT(spread.high - spread.low, 256u * 1024u) << "the host stack grew with the loop";
}

Task<void> waiter(Log& log, Event& e, std::string name) {
  co_await e.wait();
  log.add(name);
}

Task<void> notifier(Log& log, Event& e) {
  co_await log.s.delay(7);
  e.notify();
  log.add("notified");
}

TEST(Scheduler, EventWakesWaitersInOrder) {
  Scheduler s;
  Log log{s, {}};
  Event e(s);
  s.spawn("w1", waiter(log, e, "w1"));
  s.spawn("w2", waiter(log, e, "w2"));
  s.spawn("n", notifier(log, e));
  s.run();
  const std::vector<std::string> expected = {"7 notified", "7 w1", "7 w2"};
  EXPECT_EQ(log.lines, expected);
}

TEST(Scheduler, EventNotifyAtFutureTime) {
  Scheduler s;
  Log log{s, {}};
  Event e(s);
  s.spawn("w", waiter(log, e, "w"));
  e.notifyAt(1234);
  s.run();
  ASSERT_EQ(log.lines.size(), 1u);
  EXPECT_EQ(log.lines[0], "1234 w");
}

TEST(Scheduler, RunUntilStopsAndResumes) {
  Scheduler s;
  Log log{s, {}};
  s.spawn("a", sleeper(log, "a", 100, 5));
  s.runUntil(250);
  EXPECT_EQ(s.now(), 250);
  EXPECT_EQ(log.lines.size(), 2u);
  s.runUntil(250);  // nothing due
  EXPECT_EQ(log.lines.size(), 2u);
  s.runUntil(300);  // event exactly at the limit runs
  EXPECT_EQ(log.lines.size(), 3u);
  s.run();
  EXPECT_EQ(log.lines.size(), 5u);
  EXPECT_TRUE(s.idle());
}

Task<void> ticker(Log& log, Tick period, int times) {
  for (int i = 0; i < times; ++i) {
    co_await log.s.delay(period);
    log.add("tick");
  }
}

Task<void> injectFault(Scheduler& s, Process& victim, Tick at, Tick duration) {
  co_await s.until(at);
  s.suspendFor(victim, duration);
}

TEST(Scheduler, ProcessSuspendedFor500msByFaultAndResumed) {
  Scheduler s;
  Log log{s, {}};
  const Tick period = fromMs(100);
  Process& p = s.spawn("ticker", ticker(log, period, 10));
  s.spawn("fault", injectFault(s, p, fromMs(250), fromMs(500)));
  s.run();
  // Ticks at 100, 200; the tick due at 300 is held until 750; then 850, 950, ...
  std::vector<Tick> times;
  for (const auto& l : log.lines) times.push_back(std::stoll(l));
  const std::vector<Tick> expected = {fromMs(100),  fromMs(200),  fromMs(750),  fromMs(850),  fromMs(950),
                                      fromMs(1050), fromMs(1150), fromMs(1250), fromMs(1350), fromMs(1450)};
  EXPECT_EQ(times, expected);
  EXPECT_EQ(p.suspendedTotal(), fromMs(500));
  EXPECT_TRUE(p.done());
}

TEST(Scheduler, SuspendHoldsEventWakeups) {
  Scheduler s;
  Log log{s, {}};
  Event e(s);
  Process& w = s.spawn("w", waiter(log, e, "w"));
  s.runUntil(10);
  s.suspend(w);
  e.notifyAt(20);
  s.runUntil(100);
  EXPECT_TRUE(log.lines.empty());
  s.resume(w);
  s.run();
  ASSERT_EQ(log.lines.size(), 1u);
  EXPECT_EQ(log.lines[0], "100 w");
}

Task<void> thrower(Scheduler& s) {
  co_await s.delay(3);
  throw std::runtime_error("boom");
}

TEST(Scheduler, ExceptionNamesProcessAndTime) {
  Scheduler s;
  s.spawn("bad", thrower(s));
  try {
    s.run();
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'bad'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("tick 3"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("boom"), std::string::npos);
  }
}

TEST(Scheduler, UnfinishedProcessesAreDestroyedCleanly) {
  // Run under ASan/LSan in CI: frames of processes still waiting must not leak.
  Log* leakCheck = nullptr;
  {
    Scheduler s;
    Log log{s, {}};
    leakCheck = &log;
    Event never(s);
    s.spawn("w", waiter(log, never, "w"));
    s.spawn("a", sleeper(log, "a", 10, 1000));
    s.runUntil(55);
    EXPECT_EQ(log.lines.size(), 5u);
  }
  EXPECT_NE(leakCheck, nullptr);
}

TEST(Scheduler, ManyReadyEntriesKeepOrder) {
  Scheduler s;
  Log log{s, {}};
  for (int i = 0; i < 300; ++i) s.spawn("z" + std::to_string(i), zeroYield(log, std::to_string(i)));
  s.run();
  ASSERT_EQ(log.lines.size(), 600u);
  for (int i = 0; i < 300; ++i) {
    std::ostringstream first, second;
    first << "0 " << i << "1";
    second << "0 " << i << "2";
    EXPECT_EQ(log.lines[i], first.str());
    EXPECT_EQ(log.lines[300 + i], second.str());
  }
}

}  // namespace
}  // namespace vbim
