#include "runtime/shape_model.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "runtime/trace.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim {
namespace {

struct ModelRun {
  ShapeModelResult r;
  std::string json;
  std::string vcd;
};

ModelRun runWith(WorkerPool* pool, double seconds) {
  ShapeModelSettings s;
  s.duration = fromSeconds(seconds);
  s.pool = pool;
  Tracer t;
  ModelRun out{runShapeModel(s, &t), {}, {}};
  std::ostringstream j, v;
  t.writeChromeJson(j);
  t.writeVcd(v);
  out.json = j.str();
  out.vcd = v.str();
  return out;
}

TEST(ShapeModel, ConsumerBoundWithStall) {
  const ModelRun a = runWith(nullptr, 5.0);
  // Consumer-bound: 20 us per token, minus the stall (500 ms, minus the 8 tokens buffered).
  const std::uint64_t upper = fromSeconds(5.0) / fromUs(20);
  const std::uint64_t lost = (fromMs(500) - 8 * fromUs(20)) / fromUs(20);
  EXPECT_NEAR(static_cast<double>(a.r.consumed), static_cast<double>(upper - lost), 3.0);
  EXPECT_EQ(a.r.producerSuspended, fromMs(500));
  // About 30 vsyncs of the 500 ms stall see no progress.
  EXPECT_GE(a.r.starvedVsyncs, 28u);
  EXPECT_LE(a.r.starvedVsyncs, 31u);
  EXPECT_GT(a.r.producerBlocked, 0u);
}

TEST(ShapeModel, SameTraceBytesOverRepeatedRuns) {
  const ModelRun a = runWith(nullptr, 4.0);
  const ModelRun b = runWith(nullptr, 4.0);
  EXPECT_EQ(a.json, b.json);
  EXPECT_EQ(a.vcd, b.vcd);
}

TEST(ShapeModel, SameTraceBytesWithOneOrTwoPoolThreads) {
  WorkerPool one(1), two(2), none(0);
  const ModelRun a = runWith(&one, 4.0);
  const ModelRun b = runWith(&two, 4.0);
  const ModelRun c = runWith(&none, 4.0);
  EXPECT_NE(a.r.frameChecksum, 0u);
  EXPECT_EQ(a.r.frameChecksum, b.r.frameChecksum);
  EXPECT_EQ(a.r.frameChecksum, c.r.frameChecksum);
  EXPECT_EQ(a.json, b.json);
  EXPECT_EQ(a.vcd, b.vcd);
  EXPECT_EQ(a.json, c.json);
}

}  // namespace
}  // namespace vbim
