// The pictures of a run written on a host thread of their own (issue #31): the simulation copies a
// picture (a 256x256 lightmap is 256 KiB, ~0.03 ms) and goes on while the thread encodes and writes
// it, so a slow encoder (PNG at a high level, EXR) costs wall time only when the queue is full.
// Files and their bytes are what the caller's writer makes of each picture, whatever the timing:
// one thread writes them in the order given. The thread's CPU time still counts in the process's
// (std::clock): the encoder must be cheap too (imageio/png_encoder.hpp).
//
// Memory: at most `capacity` pictures wait, plus the one being written (RunDirWriter's default, 8,
// is four lightmap + sky pairs: 4.5 MiB at 512x512 + 256x128, 1.1 MiB at 256x256 + 128x64).
// Failures: the first exception a write throws is kept, the pictures after it are dropped, and it
// is thrown again (the same object) by the next push() or drain(). Destruction (a run that stops
// early, Ctrl-C) drops the pictures not started, lets the one being written finish (the writer puts
// it in place whole or removes its temporary), and joins the thread: no file is written afterwards.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "runtime/image.hpp"

namespace vbim::player {

class PictureQueue {
 public:
  // Writes a picture to a path; the picture is the queue's copy, which it may change (and which the
  // queue then reuses).
  using Write = std::function<void(const std::filesystem::path&, Rgba8Image&)>;

  // capacity >= 1. Throws vbim::Error if the host cannot start the thread.
  PictureQueue(Write write, std::size_t capacity);
  ~PictureQueue();
  PictureQueue(const PictureQueue&) = delete;
  PictureQueue& operator=(const PictureQueue&) = delete;

  // Queues a copy of `picture`, blocking while `capacity` wait. Throws an earlier write's failure.
  void push(std::filesystem::path path, const Rgba8Image& picture);
  // Returns when every picture pushed is written. Throws the first write's failure, if any.
  void drain();
  // CPU time the writer thread has used so far, in seconds (the host's per-thread CPU clock; for
  // summaries and benchmarks, never for a result).
  double cpuSeconds() const { return static_cast<double>(cpuNanoseconds_.load()) * 1e-9; }

 private:
  struct Job {
    std::filesystem::path path;
    Rgba8Image picture;
  };
  void run();

  Write write_;
  std::size_t capacity_;
  std::mutex mu_;
  std::condition_variable changed_;  // a job queued or done, an error, or stopping
  std::deque<Job> jobs_;
  // Pictures written, whose buffers the next copies reuse: fresh buffers of this size come from
  // fresh pages, and faulting those in cost more than the copy.
  std::vector<Rgba8Image> spare_;
  bool busy_ = false;  // the thread is writing a job it took from jobs_
  bool stopping_ = false;
  std::exception_ptr error_;
  std::atomic<std::int64_t> cpuNanoseconds_{0};
  std::thread thread_;  // last: started once every member above exists
};

}  // namespace vbim::player
