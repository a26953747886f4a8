// The scheduler's order (time, then insertion) against the scheduler it replaced, kept as
// bench/runtime/baseline_scheduler.hpp: random models of sleepers with tied, zero and spread
// delays plus a producer/consumer pair on a bounded channel (wake-ups at the current time), run in
// random runUntil() slices, must log the same (time, process, step) sequence on both. Two such
// models in the two lanes must each log what they log alone, the first lane's steps ahead at ties.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bench/runtime/baseline_scheduler.hpp"
#include "bench/runtime/cost_model.hpp"
#include "runtime/scheduler.hpp"

namespace vbim {
namespace {

struct Step {
  Tick time;
  int process;
  int step;
  bool operator==(const Step&) const = default;
};

template <class S>
Task<void> sleeper(S& s, std::vector<Step>& log, int id, std::vector<Tick> delays) {
  for (std::size_t i = 0; i < delays.size(); ++i) {
    co_await s.delay(delays[i]);
    log.push_back({s.now(), id, static_cast<int>(i)});
  }
}

template <class S>
Task<void> producer(S& s, bench::Channel<S>& ch, std::vector<Step>& log, int id, std::vector<Tick> delays) {
  for (std::size_t i = 0; i < delays.size(); ++i) {
    co_await s.delay(delays[i]);
    co_await ch.push(i);
    log.push_back({s.now(), id, static_cast<int>(i)});
  }
}

template <class S>
Task<void> consumer(S& s, bench::Channel<S>& ch, std::vector<Step>& log, int id, std::vector<Tick> delays) {
  for (std::size_t i = 0; i < delays.size(); ++i) {
    const std::uint64_t v = co_await ch.pop();
    log.push_back({s.now(), id, static_cast<int>(v)});
    co_await s.delay(delays[i]);
  }
}

struct Plan {
  std::vector<std::vector<Tick>> sleepers;
  std::vector<Tick> produce, consume;
  std::vector<Tick> slices;  // runUntil() limits, ascending
};

Plan randomPlan(std::mt19937_64& rng) {
  auto delay = [&rng]() -> Tick {
    switch (rng() % 4) {
      case 0:
        return 0;
      case 1:
        return static_cast<Tick>(rng() % 3);  // many ties
      case 2:
        return static_cast<Tick>(5 * (rng() % 4));
      default:
        return static_cast<Tick>(rng() % 200);
    }
  };
  Plan p;
  p.sleepers.resize(1 + rng() % 8);
  for (auto& d : p.sleepers) d.resize(rng() % 40);
  for (auto& d : p.sleepers) {
    for (auto& t : d) t = delay();
  }
  p.produce.resize(rng() % 60);
  p.consume.resize(p.produce.size());
  for (auto& t : p.produce) t = delay();
  for (auto& t : p.consume) t = delay();
  Tick t = 0;
  while (t < 3000) {
    t += static_cast<Tick>(rng() % 120);
    p.slices.push_back(t);
  }
  return p;
}

template <class S>
std::vector<Step> play(const Plan& plan) {
  S s;
  bench::Channel<S> ch(s);
  std::vector<Step> log;
  int id = 0;
  for (const auto& d : plan.sleepers) s.spawn("sleeper", sleeper(s, log, id++, d));
  s.spawn("producer", producer(s, ch, log, 100, plan.produce));
  s.spawn("consumer", consumer(s, ch, log, 101, plan.consume));
  for (Tick t : plan.slices) {
    s.runUntil(t);
    log.push_back({s.now(), -1, static_cast<int>(s.eventsProcessed())});  // slice ends: same time and count
  }
  s.run();
  log.push_back({s.now(), -2, static_cast<int>(s.eventsProcessed())});
  return log;
}

TEST(SchedulerOrder, SameAsTheBaselineSchedulerOnRandomModels) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 400; ++trial) {
    const Plan plan = randomPlan(rng);
    const auto now = play<Scheduler>(plan);
    const auto before = play<baseline::Scheduler>(plan);
    ASSERT_EQ(now.size(), before.size()) << "trial " << trial;
    for (std::size_t i = 0; i < now.size(); ++i) {
      ASSERT_EQ(now[i], before[i]) << "trial " << trial << " entry " << i << ": time " << now[i].time << " process "
                                   << now[i].process << " against time " << before[i].time << " process "
                                   << before[i].process;
    }
  }
}

// Two random models in one scheduler, model A spawned from inside a LaneScope of `laneA` (each of
// its processes in that lane) after model B in the normal lane; each model's steps in its own log,
// and every step of both in `merged` (model 0 is A) in the order they ran.
struct TwoModels {
  std::vector<Step> a, b;
  std::vector<std::pair<Tick, int>> merged;
};

Task<void> lanedSleeper(Scheduler& s, std::vector<Step>& log, std::vector<std::pair<Tick, int>>& merged, int model,
                        int id, std::vector<Tick> delays) {
  for (std::size_t i = 0; i < delays.size(); ++i) {
    co_await s.delay(delays[i]);
    log.push_back({s.now(), id, static_cast<int>(i)});
    merged.emplace_back(s.now(), model);
  }
}

void spawnModel(Scheduler& s, bench::Channel<Scheduler>& ch, const Plan& plan, std::vector<Step>& log,
                std::vector<std::pair<Tick, int>>& merged, int model) {
  int id = 0;
  for (const auto& d : plan.sleepers) s.spawn("sleeper", lanedSleeper(s, log, merged, model, id++, d));
  s.spawn("producer", producer(s, ch, log, 100, plan.produce));
  s.spawn("consumer", consumer(s, ch, log, 101, plan.consume));
}

TwoModels playTwo(const Plan& a, const Plan& b, Lane laneA, const std::vector<Tick>& slices) {
  Scheduler s;
  bench::Channel<Scheduler> chA(s);
  bench::Channel<Scheduler> chB(s);
  TwoModels out;
  spawnModel(s, chB, b, out.b, out.merged, 1);
  {
    const Scheduler::LaneScope scope(s, laneA);
    spawnModel(s, chA, a, out.a, out.merged, 0);
  }
  for (Tick t : slices) s.runUntil(t);
  s.run();
  return out;
}

std::vector<Step> withoutSliceMarks(std::vector<Step> log) {
  std::erase_if(log, [](const Step& st) { return st.process < 0; });
  return log;
}

TEST(SchedulerOrder, EachLaneRunsAsIfAloneAndTheFirstGoesFirstAtATick) {
  std::mt19937_64 rng(29);
  int sharedTicks = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Plan a = randomPlan(rng);
    const Plan b = randomPlan(rng);
    const auto aloneA = withoutSliceMarks(play<Scheduler>(a));
    const auto aloneB = withoutSliceMarks(play<Scheduler>(b));
    const TwoModels laned = playTwo(a, b, Lane::First, a.slices);
    // Each model's own steps are those it makes alone, in the same order: the lane changes only
    // which model runs first at a tick both have entries at.
    ASSERT_EQ(laned.a, aloneA) << "trial " << trial;
    ASSERT_EQ(laned.b, aloneB) << "trial " << trial;
    for (std::size_t i = 1; i < laned.merged.size(); ++i) {
      const auto& [t0, m0] = laned.merged[i - 1];
      const auto& [t1, m1] = laned.merged[i];
      ASSERT_LE(t0, t1) << "trial " << trial;
      // At one tick, no step of the first lane's model after one of the normal lane's.
      if (t0 == t1 && m0 == 1) {
        ASSERT_EQ(m1, 1) << "trial " << trial << " tick " << t0;
      }
      if (t0 == t1 && m0 != m1) ++sharedTicks;
    }
    // In the same lane, the later spawned model no longer goes first at shared ticks.
    const TwoModels same = playTwo(a, b, Lane::Normal, a.slices);
    ASSERT_EQ(same.a, aloneA) << "trial " << trial;
    ASSERT_EQ(same.b, aloneB) << "trial " << trial;
  }
  EXPECT_GT(sharedTicks, 100);  // the models did meet at ticks (the check above had work to do)
}

// A process spawned by a process is in its lane; an event notified by a first-lane process at a
// later time wakes its waiters in their own lanes.
Task<void> child(Scheduler& s, std::vector<std::string>& log, std::string name) {
  co_await s.delay(5);
  log.push_back(name + "@" + std::to_string(s.now()));
}

Task<void> parent(Scheduler& s, std::vector<std::string>& log, std::string name) {
  s.spawn(name + ".child", child(s, log, name + ".child"));
  co_await s.delay(5);
  log.push_back(name + "@" + std::to_string(s.now()));
}

TEST(SchedulerOrder, SpawnedProcessesInheritTheirParentsLane) {
  Scheduler s;
  std::vector<std::string> log;
  s.spawn("normal", parent(s, log, "normal"));
  Process* first = nullptr;
  {
    const Scheduler::LaneScope scope(s, Lane::First);
    first = &s.spawn("first", parent(s, log, "first"));
  }
  EXPECT_EQ(first->lane(), Lane::First);
  s.run();
  const std::vector<std::string> expected = {"first@5", "first.child@5", "normal@5", "normal.child@5"};
  EXPECT_EQ(log, expected);
}

// A process whose wake-up is the next entry anyway continues without a queue round trip; one whose
// wake-up ties with an entry already queued waits its turn behind it.
Task<void> stepper(Scheduler& s, std::vector<Step>& log, int id, Tick d, int n) {
  for (int i = 0; i < n; ++i) {
    co_await s.delay(d);
    log.push_back({s.now(), id, i});
  }
}

TEST(SchedulerOrder, TiesAfterAContinuationKeepInsertionOrder) {
  Scheduler s;
  std::vector<Step> log;
  s.spawn("fast", stepper(s, log, 0, 1, 6));  // wakes at 1..6, alone until 4
  s.spawn("slow", stepper(s, log, 1, 4, 1));  // queued at time 0 for 4: before fast's wake-up at 4
  s.run();
  const std::vector<Step> expected = {{1, 0, 0}, {2, 0, 1}, {3, 0, 2}, {4, 1, 0}, {4, 0, 3}, {5, 0, 4}, {6, 0, 5}};
  EXPECT_EQ(log, expected);
  EXPECT_EQ(s.eventsProcessed(), 9u);  // two starts and seven wake-ups, continuations included
}

}  // namespace
}  // namespace vbim
