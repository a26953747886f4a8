// Same disc, config, fault plan and seed: the same hashes.txt, trace.json and signals.vcd, bit for
// bit, run after run, while the machine is busy, and whether the IPU's picture decode runs on the
// simulation thread or is split by slice rows over host threads (`vbim play --threads`).
#include <gtest/gtest.h>

#include <atomic>
#include <sstream>
#include <thread>
#include <vector>

#include "ipu/pool_runner.hpp"
#include "player/report.hpp"
#include "player/scenario.hpp"
#include "runtime/worker_pool.hpp"
#include "tests/player/sample_path.hpp"

namespace vbim::player {
namespace {

struct Outputs {
  std::string hashes, trace, vcd, stats;
};

Outputs runOnce(ipu::SliceRunner* runner = nullptr) {
  Kernels k;
  k.sliceRunner = runner;
  auto run = Scenario::bareFile(testing::samplePath("day_weather.vbim"))
                 .kernels(k)
                 .seed(9)
                 .stall(fromMs(300), fromMs(4'000))
                 .readError(30, 300)
                 .branch(fromMs(7'000), 1)
                 .start(fromMs(10'000));
  run->runToEnd();
  Outputs o;
  for (const VsyncRow& r : run->rows()) o.hashes += hashesLine(r);
  std::ostringstream t, v;
  run->player().tracer().writeChromeJson(t);
  run->player().tracer().writeVcd(v);
  o.trace = t.str();
  o.vcd = v.str();
  o.stats = run->statsJson();
  return o;
}

TEST(PlayerDeterminism, RepeatedRunsAreIdentical) {
  const Outputs a = runOnce();
  const Outputs b = runOnce();
  EXPECT_FALSE(a.hashes.empty());
  EXPECT_EQ(a.hashes, b.hashes);
  EXPECT_EQ(a.trace, b.trace);
  EXPECT_EQ(a.vcd, b.vcd);
  EXPECT_EQ(a.stats, b.stats);
}

TEST(PlayerDeterminism, IdenticalWhileTheMachineIsBusy) {
  const Outputs quiet = runOnce();
  std::atomic<bool> stop{false};
  std::vector<std::thread> spinners;
  for (int i = 0; i < 3; ++i) {
    spinners.emplace_back([&stop] {
      volatile std::uint64_t x = 0;
      while (!stop.load(std::memory_order_relaxed)) x = x + 1;
    });
  }
  const Outputs busy = runOnce();
  stop = true;
  for (auto& t : spinners) t.join();
  EXPECT_EQ(quiet.hashes, busy.hashes);
  EXPECT_EQ(quiet.trace, busy.trace);
  EXPECT_EQ(quiet.vcd, busy.vcd);
}

TEST(PlayerDeterminism, SliceParallelDecodeOnHostThreadsChangesNothing) {
  const Outputs alone = runOnce();
  for (unsigned helpers : {1u, 3u}) {
    WorkerPool pool(helpers);
    ipu::PoolSliceRunner runner(pool);
    const Outputs split = runOnce(&runner);
    EXPECT_FALSE(split.hashes.empty());
    EXPECT_EQ(alone.hashes, split.hashes) << helpers;
    EXPECT_EQ(alone.trace, split.trace) << helpers;
    EXPECT_EQ(alone.vcd, split.vcd) << helpers;
    EXPECT_EQ(alone.stats, split.stats) << helpers;
  }
}

TEST(PlayerDeterminism, AnotherSeedChangesTheDriveLatencies) {
  auto a = Scenario::bareFile(testing::samplePath("day_clear.vbim")).seed(1).start(fromMs(3'000));
  auto b = Scenario::bareFile(testing::samplePath("day_clear.vbim")).seed(2).start(fromMs(3'000));
  a->runToEnd();
  b->runToEnd();
  EXPECT_NE(a->player().pipeline().ring().readLog(), b->player().pipeline().ring().readLog());
}

}  // namespace
}  // namespace vbim::player
