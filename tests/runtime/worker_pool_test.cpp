#include "runtime/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace vbim {
namespace {

TEST(WorkerPool, ParallelForCoversEveryIndexOnce) {
  for (unsigned threads : {0u, 1u, 2u, 4u}) {
    WorkerPool pool(threads);
    std::vector<int> hits(1000, 0);
    pool.parallelFor(hits.size(), [&](std::size_t i) { hits[i] += 1; });
    EXPECT_EQ(std::accumulate(hits.begin(), hits.end(), 0), 1000) << threads;
    for (int h : hits) EXPECT_EQ(h, 1);
  }
}

TEST(WorkerPool, SubmitThenWaitLater) {
  WorkerPool pool(2);
  std::vector<std::uint64_t> out(64);
  auto b = pool.submit(out.size(), [&](std::size_t i) { out[i] = i * i; });
  b->wait();
  EXPECT_TRUE(b->finished());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], i * i);
}

TEST(WorkerPool, ExceptionsReachTheWaiter) {
  WorkerPool pool(2);
  auto b = pool.submit(10, [](std::size_t i) {
    if (i == 7) throw std::runtime_error("row 7");
  });
  EXPECT_THROW(b->wait(), std::runtime_error);
}

TEST(WorkerPool, ManyBatchesInterleaved) {
  WorkerPool pool(2);
  std::atomic<int> total{0};
  std::vector<std::shared_ptr<WorkerPool::Batch>> batches;
  for (int k = 0; k < 50; ++k) batches.push_back(pool.submit(20, [&](std::size_t) { total.fetch_add(1); }));
  for (auto& b : batches) b->wait();
  EXPECT_EQ(total.load(), 1000);
}

}  // namespace
}  // namespace vbim
