#include "runtime/fifo.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace vbim {
namespace {

struct Rig {
  Scheduler s;
  Fifo<int> f{s, 3, "f"};
  std::vector<std::pair<Tick, int>> got;
  std::vector<Tick> pushedAt;
};

Task<void> fastProducer(Rig& r, int n) {
  for (int i = 0; i < n; ++i) {
    co_await r.f.push(i);
    r.pushedAt.push_back(r.s.now());
  }
}

Task<void> slowConsumer(Rig& r, int n, Tick cost) {
  for (int i = 0; i < n; ++i) {
    co_await r.s.delay(cost);
    const int v = co_await r.f.pop();
    r.got.emplace_back(r.s.now(), v);
  }
}

TEST(Fifo, BackPressureBlocksProducerUntilSpace) {
  Rig r;
  r.s.spawn("p", fastProducer(r, 6));
  r.s.spawn("c", slowConsumer(r, 6, 10));
  r.s.run();
  // Three pushes complete at once (depth 3); each later push completes when a pop frees a slot.
  const std::vector<Tick> expectedPush = {0, 0, 0, 10, 20, 30};
  EXPECT_EQ(r.pushedAt, expectedPush);
  ASSERT_EQ(r.got.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(r.got[i].second, i);
    EXPECT_EQ(r.got[i].first, 10 * (i + 1));
  }
}

Task<void> lateProducer(Rig& r, Tick at, int v) {
  co_await r.s.until(at);
  co_await r.f.push(v);
}

Task<void> eagerConsumer(Rig& r, int n) {
  for (int i = 0; i < n; ++i) {
    const int v = co_await r.f.pop();
    r.got.emplace_back(r.s.now(), v);
  }
}

TEST(Fifo, PopBlocksUntilData) {
  Rig r;
  r.s.spawn("c", eagerConsumer(r, 2));
  r.s.spawn("p1", lateProducer(r, 50, 7));
  r.s.spawn("p2", lateProducer(r, 90, 8));
  r.s.run();
  const std::vector<std::pair<Tick, int>> expected = {{50, 7}, {90, 8}};
  EXPECT_EQ(r.got, expected);
  EXPECT_TRUE(r.f.empty());
}

TEST(Fifo, TryVariants) {
  Scheduler s;
  Fifo<int> f(s, 2);
  EXPECT_TRUE(f.tryPush(1));
  EXPECT_TRUE(f.tryPush(2));
  EXPECT_FALSE(f.tryPush(3));
  EXPECT_TRUE(f.full());
  EXPECT_EQ(f.tryPop(), 1);
  EXPECT_EQ(f.tryPop(), 2);
  EXPECT_EQ(f.tryPop(), std::nullopt);
}

}  // namespace
}  // namespace vbim
