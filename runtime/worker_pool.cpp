#include "runtime/worker_pool.hpp"

#include <string>
#include <system_error>

#include "runtime/error.hpp"

namespace vbim {

// A thread the host cannot start (thread or memory limits) is an error the caller reports: the
// threads already running are stopped and joined first (destroying a joinable std::thread would
// call std::terminate).
WorkerPool::WorkerPool(unsigned threads, std::chrono::microseconds spin) : spin_(spin) {
  workers_.reserve(threads);
  try {
    for (unsigned i = 0; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
  } catch (const std::system_error& e) {
    const std::size_t started = workers_.size();
    stop();
    throw Error("cannot start host thread " + std::to_string(started + 1) + " of " + std::to_string(threads) + ": " +
                e.what() + " (use fewer threads, or raise the process or memory limit)");
  }
}

WorkerPool::~WorkerPool() {
  stop();
}

void WorkerPool::stop() {
  {
    std::lock_guard lock(mu_);
    stopping_ = true;
    submissions_.fetch_add(1, std::memory_order_release);
  }
  work_.notify_all();
  for (auto& t : workers_) t.join();
  workers_.clear();
}

std::shared_ptr<WorkerPool::Batch> WorkerPool::submit(std::size_t count, std::function<void(std::size_t)> fn) {
  auto b = std::make_shared<Batch>();
  b->pool_ = this;
  b->fn_ = std::move(fn);
  b->count_ = count;
  if (count == 0) return b;
  {
    std::lock_guard lock(mu_);
    queue_.push_back(b);
    submissions_.fetch_add(1, std::memory_order_release);
  }
  work_.notify_all();
  return b;
}

void WorkerPool::parallelFor(std::size_t count, std::function<void(std::size_t)> fn) {
  submit(count, std::move(fn))->wait();
}

// Takes one item of the oldest batch with items left and runs it with the lock released.
// Returns false when there is nothing to take.
bool WorkerPool::runOne(std::unique_lock<std::mutex>& lock) {
  while (!queue_.empty() && queue_.front()->next_ >= queue_.front()->count_) queue_.pop_front();
  if (queue_.empty()) return false;
  std::shared_ptr<Batch> b = queue_.front();
  const std::size_t i = b->next_++;
  lock.unlock();
  std::exception_ptr err;
  try {
    b->fn_(i);
  } catch (...) {
    err = std::current_exception();
  }
  lock.lock();
  if (err && !b->error_) b->error_ = err;
  if (b->done_.fetch_add(1, std::memory_order_release) + 1 == b->count_) done_.notify_all();
  return true;
}

template <class Ready>
void WorkerPool::poll(Ready&& ready) const {
  if (spin_.count() <= 0) return;
  const auto until = std::chrono::steady_clock::now() + spin_;
  while (!ready() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
}

void WorkerPool::workerLoop() {
  std::unique_lock lock(mu_);
  for (;;) {
    if (runOne(lock)) continue;
    if (stopping_) return;
    // Nothing to take: poll for the next submission before sleeping (a condition variable with no
    // sleeper costs the submitter no system call).
    const std::uint64_t seen = submissions_.load(std::memory_order_relaxed);
    lock.unlock();
    poll([&] { return submissions_.load(std::memory_order_acquire) != seen; });
    lock.lock();
    work_.wait(lock, [&] { return submissions_.load(std::memory_order_relaxed) != seen; });
  }
}

void WorkerPool::Batch::wait() {
  if (count_ == 0) return;
  WorkerPool& pool = *pool_;
  std::unique_lock lock(pool.mu_);
  // Help with this batch's remaining items, then wait for items other threads hold.
  while (next_ < count_) {
    const std::size_t i = next_++;
    lock.unlock();
    std::exception_ptr err;
    try {
      fn_(i);
    } catch (...) {
      err = std::current_exception();
    }
    lock.lock();
    if (err && !error_) error_ = err;
    done_.fetch_add(1, std::memory_order_release);
  }
  if (done_.load(std::memory_order_relaxed) != count_) {
    lock.unlock();
    pool.poll([this] { return done_.load(std::memory_order_acquire) == count_; });
    lock.lock();
  }
  pool.done_.wait(lock, [this] { return done_.load(std::memory_order_relaxed) == count_; });
  if (error_) std::rethrow_exception(error_);
}

bool WorkerPool::Batch::finished() const {
  std::lock_guard lock(pool_->mu_);
  return done_ == count_;
}

}  // namespace vbim
