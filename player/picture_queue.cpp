#include "player/picture_queue.hpp"

#include <pthread.h>
#include <time.h>

#include <string>
#include <system_error>
#include <utility>

#include "runtime/error.hpp"

namespace vbim::player {

namespace {

std::int64_t threadCpuNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

}  // namespace

PictureQueue::PictureQueue(Write write, std::size_t capacity)
    : write_(std::move(write)), capacity_(capacity < 1 ? 1 : capacity) {
  try {
    thread_ = std::thread([this] { run(); });
    // Named so that perf, top and bench/player/image_share.sh can tell it from the simulation's.
    pthread_setname_np(thread_.native_handle(), "vbim-pictures");
  } catch (const std::system_error& e) {
    throw Error(std::string("cannot start the thread that writes the pictures: ") + e.what());
  }
}

PictureQueue::~PictureQueue() {
  {
    const std::lock_guard<std::mutex> lock(mu_);
    stopping_ = true;
    jobs_.clear();
  }
  changed_.notify_all();
  thread_.join();
}

void PictureQueue::push(std::filesystem::path path, const Rgba8Image& picture) {
  std::unique_lock<std::mutex> lock(mu_);
  changed_.wait(lock, [this] { return jobs_.size() < capacity_ || error_; });
  if (error_) std::rethrow_exception(error_);
  Rgba8Image copy;
  if (!spare_.empty()) {
    copy = std::move(spare_.back());
    spare_.pop_back();
  }
  lock.unlock();
  copy.width = picture.width;
  copy.height = picture.height;
  copy.pixels.assign(picture.pixels.begin(), picture.pixels.end());
  lock.lock();
  jobs_.push_back(Job{std::move(path), std::move(copy)});
  lock.unlock();
  changed_.notify_all();
}

void PictureQueue::drain() {
  std::unique_lock<std::mutex> lock(mu_);
  changed_.wait(lock, [this] { return (jobs_.empty() && !busy_) || error_; });
  if (error_) std::rethrow_exception(error_);
}

void PictureQueue::run() {
  std::unique_lock<std::mutex> lock(mu_);
  for (;;) {
    changed_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
    if (stopping_) break;
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    busy_ = true;
    lock.unlock();
    changed_.notify_all();  // a place in the queue is free
    std::exception_ptr failed;
    try {
      write_(job.path, job.picture);
    } catch (...) {
      failed = std::current_exception();
    }
    cpuNanoseconds_.store(threadCpuNanoseconds());
    lock.lock();
    busy_ = false;
    if (spare_.size() <= capacity_) spare_.push_back(std::move(job.picture));
    if (failed && !error_) {
      error_ = failed;
      jobs_.clear();  // what comes after a failed file is not written
    }
    changed_.notify_all();
  }
  cpuNanoseconds_.store(threadCpuNanoseconds());
}

}  // namespace vbim::player
