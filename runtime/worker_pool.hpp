// A pool of real host threads for data-parallel pixel work (slice-parallel decode, row-parallel
// blend). Jobs write disjoint outputs, so results never depend on which thread ran what. The
// simulation takes the results at a modelled simulated time, never "when they finish":
//
//   auto batch = pool.submit(slices, decodeSlice);   // host threads start now
//   co_await sched.delay(modelledDecodeCost);         // simulated time passes
//   batch->wait();                                    // join on the host; values are now used
//
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace vbim {

class WorkerPool {
 public:
  class Batch {
   public:
    // Blocks the host until every item of the batch is done; the caller helps run items.
    void wait();
    bool finished() const;

   private:
    friend class WorkerPool;
    WorkerPool* pool_ = nullptr;
    std::function<void(std::size_t)> fn_;
    std::size_t count_ = 0;
    std::size_t next_ = 0;  // guarded by pool mutex
    std::size_t done_ = 0;  // guarded by pool mutex
    std::exception_ptr error_;
  };

  // threads = number of host threads besides the caller; 0 runs everything on the caller.
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()); }

  // Starts fn(0..count-1) on the pool and returns at once.
  std::shared_ptr<Batch> submit(std::size_t count, std::function<void(std::size_t)> fn);
  // Runs fn(0..count-1) and returns when all are done (the caller takes part).
  void parallelFor(std::size_t count, std::function<void(std::size_t)> fn);

 private:
  bool runOne(std::unique_lock<std::mutex>& lock);
  void workerLoop();

  std::mutex mu_;
  std::condition_variable work_;
  std::condition_variable done_;
  std::deque<std::shared_ptr<Batch>> queue_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace vbim
