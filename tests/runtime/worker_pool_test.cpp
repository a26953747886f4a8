#include "runtime/worker_pool.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "runtime/error.hpp"

namespace vbim {
namespace {

// In a child process (the limit must not outlive the test): with the address space limited to
// what is in use plus a few thread stacks, the pool cannot start 64 threads. It must report that
// as a vbim::Error after joining the threads it did start; before, the joinable threads were
// destroyed during the unwind and std::terminate aborted the process.
TEST(WorkerPoolDeathTest, ThreadThatCannotStartIsAnErrorNotAnAbort) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "sanitizer shadow memory does not fit under an address-space limit";
#else
  EXPECT_EXIT(
      {
        WorkerPool warm(1);  // the runtime's first-thread allocations, outside the limit
        rlimit limit{};
        getrlimit(RLIMIT_AS, &limit);
        std::size_t inUse = 0;
        if (FILE* f = std::fopen("/proc/self/statm", "r")) {
          if (std::fscanf(f, "%zu", &inUse) != 1) inUse = 0;
          std::fclose(f);
        }
        inUse *= 4096;
        limit.rlim_cur = inUse + 48u * 1024 * 1024;  // room for a few 8 MiB stacks, not 64
        setrlimit(RLIMIT_AS, &limit);
        try {
          WorkerPool pool(64);
        } catch (const Error& e) {
          std::fprintf(stderr, "%s\n", e.what());
          std::exit(3);
        }
        std::exit(0);
      },
      testing::ExitedWithCode(3), "cannot start host thread [0-9]+ of 64");
#endif
}

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

// Back-to-back batches meet polling workers, batches after a pause meet sleeping ones; with any
// spin time every index runs once.
TEST(WorkerPool, PollingAndSleepingWorkersBothRunEveryIndexOnce) {
  using std::chrono::microseconds;
  for (const microseconds spin : {microseconds(0), microseconds(100), WorkerPool::kDefaultSpin}) {
    WorkerPool pool(2, spin);
    for (int batch = 0; batch < 40; ++batch) {
      if (batch % 10 == 9) std::this_thread::sleep_for(microseconds(2000));  // past the spin: workers sleep
      std::vector<std::atomic<int>> hits(batch % 7 + 1);
      pool.parallelFor(hits.size(), [&](std::size_t i) { hits[i].fetch_add(1); });
      for (const auto& h : hits) ASSERT_EQ(h.load(), 1) << spin.count() << " " << batch;
    }
  }
}

// A worker that went to sleep after its spin still wakes for the next batch: two items that each
// wait for the other can only finish if the caller and the worker run them at the same time.
TEST(WorkerPool, SleepingWorkerWakesForTheNextBatch) {
  WorkerPool pool(1, std::chrono::microseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::mutex mu;
  std::condition_variable cv;
  int arrived = 0;
  bool together = true;
  pool.parallelFor(2, [&](std::size_t) {
    std::unique_lock lock(mu);
    ++arrived;
    cv.notify_all();
    if (!cv.wait_for(lock, std::chrono::seconds(10), [&] { return arrived == 2; })) together = false;
  });
  EXPECT_TRUE(together);
}

}  // namespace
}  // namespace vbim
