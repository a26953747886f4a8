// A pool of real host threads for data-parallel pixel work (slice-parallel decode, row-parallel
// blend). Jobs write disjoint outputs, so results never depend on which thread ran what. The
// simulation takes the results at a modelled simulated time, never "when they finish":
//
//   auto batch = pool.submit(slices, decodeSlice);   // host threads start now
//   co_await sched.delay(modelledDecodeCost);         // simulated time passes
//   batch->wait();                                    // join on the host; values are now used
//
// An idle thread polls (yielding its core to anyone who wants it) for a short while before it
// sleeps, and so does a caller waiting for the last items of a batch. Waking a sleeping thread
// costs a futex wake and a scheduler decision, tens of microseconds on a virtual machine, which is
// as long as a whole slice job of a small picture: with sleeping workers, slice-parallel decode of
// 512x512 pictures on 2 threads was 1.1-1.5x one thread, with polling workers 1.8-2x
// (bench/ipu, BM_SliceParallel). The spin reads the host's steady clock; no result depends on it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
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
    std::size_t next_ = 0;               // guarded by pool mutex
    std::atomic<std::size_t> done_ = 0;  // written under the pool mutex, polled without it
    std::exception_ptr error_;
  };

  static constexpr std::chrono::microseconds kDefaultSpin{500};

  // threads = number of host threads besides the caller; 0 runs everything on the caller.
  // spin = how long an idle thread (or a waiting caller) polls before it sleeps; 0 never polls.
  // Throws vbim::Error (runtime/error.hpp) if the host cannot start one of the threads.
  explicit WorkerPool(unsigned threads, std::chrono::microseconds spin = kDefaultSpin);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()); }

  // Starts fn(0..count-1) on the pool and returns at once.
  std::shared_ptr<Batch> submit(std::size_t count, std::function<void(std::size_t)> fn);
  // Runs fn(0..count-1) and returns when all are done (the caller takes part).
  void parallelFor(std::size_t count, std::function<void(std::size_t)> fn);

 private:
  void stop();  // wakes and joins every worker
  bool runOne(std::unique_lock<std::mutex>& lock);
  void workerLoop();
  template <class Ready>
  void poll(Ready&& ready) const;  // yields until ready() or the spin time has passed

  std::mutex mu_;
  std::condition_variable work_;
  std::condition_variable done_;
  std::deque<std::shared_ptr<Batch>> queue_;
  bool stopping_ = false;
  std::atomic<std::uint64_t> submissions_{0};  // bumped (under mu_) per submit and on shutdown
  std::chrono::microseconds spin_;
  std::vector<std::thread> workers_;
};

}  // namespace vbim
