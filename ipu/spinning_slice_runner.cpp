#include "ipu/spinning_slice_runner.hpp"

namespace vbim::ipu {

SpinningSliceRunner::SpinningSliceRunner(unsigned threads, std::chrono::microseconds spin) : spin_(spin) {
  threads_.reserve(threads);
  for (unsigned i = 0; i < threads; ++i) threads_.emplace_back([this] { workerLoop(); });
}

SpinningSliceRunner::~SpinningSliceRunner() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (auto& t : threads_) t.join();
}

template <class Done>
void SpinningSliceRunner::poll(Done&& done) const {
  const auto until = std::chrono::steady_clock::now() + spin_;
  while (!done() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
}

bool SpinningSliceRunner::takeAndRun(std::unique_lock<std::mutex>& lock) {
  if (fn_ == nullptr || next_ >= count_) return false;
  const std::size_t k = next_++;
  const std::function<void(std::size_t)>& fn = *fn_;
  lock.unlock();
  std::exception_ptr err;
  try {
    fn(k);
  } catch (...) {
    err = std::current_exception();
  }
  lock.lock();
  if (err && !error_) error_ = err;
  if (done_.fetch_add(1, std::memory_order_release) + 1 == count_) finished_.notify_all();
  return true;
}

void SpinningSliceRunner::workerLoop() {
  std::uint64_t seen = 0;
  for (;;) {
    poll([&] { return generation_.load(std::memory_order_acquire) != seen; });
    std::unique_lock lock(mu_);
    wake_.wait(lock, [&] { return generation_.load(std::memory_order_relaxed) != seen; });
    seen = generation_.load(std::memory_order_relaxed);
    if (stop_) return;
    while (takeAndRun(lock)) {
    }
  }
}

void SpinningSliceRunner::run(std::size_t count, const std::function<void(std::size_t)>& fn) {
  if (threads_.empty() || count <= 1) {
    for (std::size_t k = 0; k < count; ++k) fn(k);
    return;
  }
  std::unique_lock lock(mu_);
  fn_ = &fn;
  count_ = count;
  next_ = 0;
  done_.store(0, std::memory_order_relaxed);
  error_ = nullptr;
  generation_.fetch_add(1, std::memory_order_release);
  lock.unlock();
  wake_.notify_all();  // threads still polling see the new generation without it
  lock.lock();
  while (takeAndRun(lock)) {
  }
  lock.unlock();
  poll([&] { return done_.load(std::memory_order_acquire) == count; });
  lock.lock();
  finished_.wait(lock, [&] { return done_.load(std::memory_order_relaxed) == count; });
  fn_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

}  // namespace vbim::ipu
