// The kernel's scheduler as it was before direct continuation (runtime/scheduler.*
// at commit 4ddf135): a binary min-heap on a 128-bit (time, seq) key and a FIFO ring of entries due
// now. Kept as the baseline of bench_scheduler_cost and as the order reference of
// tests/runtime/scheduler_order_test.cpp. Trimmed to what those use: spawn, delay/until, wakeNow,
// run/runUntil (no Event notification, no suspension from outside).
#pragma once

#include <coroutine>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/clock.hpp"
#include "runtime/task.hpp"

namespace vbim::baseline {

class Process {
 public:
  bool done() const { return done_; }

 private:
  friend class Scheduler;
  std::string name_;
  std::coroutine_handle<Task<void>::promise_type> root_;
  bool done_ = false;
};

class Scheduler {
 public:
  Scheduler() : ready_(64) {}
  ~Scheduler() {
    for (auto& p : processes_) {
      if (p->root_) p->root_.destroy();
    }
  }
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  Process& spawn(std::string name, Task<void> task) {
    auto proc = std::make_unique<Process>();
    proc->name_ = std::move(name);
    proc->root_ = task.release();
    proc->root_.promise().rootDone = &proc->done_;
    Process& p = *proc;
    processes_.push_back(std::move(proc));
    pushReady(p.root_.address(), &p);
    return p;
  }

  Tick now() const { return now_; }
  Process* current() const { return current_; }
  std::uint64_t eventsProcessed() const { return events_; }

  Tick run() {
    Entry e;
    while (popNext(kNever, e)) dispatch(e);
    return now_;
  }
  void runUntil(Tick t) {
    Entry e;
    while (popNext(t, e)) dispatch(e);
    if (t > now_) now_ = t;
  }

  struct DelayAwaiter {
    Scheduler& s;
    Tick d;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> h) const { s.scheduleAt(s.now_ + d, h.address(), s.current_); }
    void await_resume() const noexcept {}
  };
  DelayAwaiter delay(Tick d) { return DelayAwaiter{*this, d < 0 ? 0 : d}; }
  DelayAwaiter until(Tick t) { return DelayAwaiter{*this, t > now_ ? t - now_ : 0}; }

  void wakeNow(std::coroutine_handle<> h, Process* p) { pushReady(h.address(), p); }

 private:
  struct Entry {
    unsigned __int128 key;
    void* target;
    Process* proc;
    Tick time() const { return static_cast<Tick>(key >> 64); }
  };
  static unsigned __int128 makeKey(Tick t, std::uint64_t seq) {
    return (static_cast<unsigned __int128>(t) << 64) | seq;
  }

  void scheduleAt(Tick t, void* target, Process* p) {
    if (t <= now_) {
      pushReady(target, p);
      return;
    }
    heapPush(Entry{makeKey(t, seq_++), target, p});
  }
  void heapPush(const Entry& e) {
    heap_.push_back(e);
    std::size_t i = heap_.size() - 1;
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (heap_[parent].key <= e.key) break;
      heap_[i] = heap_[parent];
      i = parent;
    }
    heap_[i] = e;
  }
  Entry heapPop() {
    const Entry top = heap_.front();
    const Entry last = heap_.back();
    heap_.pop_back();
    const std::size_t n = heap_.size();
    if (n != 0) {
      std::size_t i = 0;
      for (;;) {
        std::size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && heap_[child + 1].key < heap_[child].key) ++child;
        if (last.key <= heap_[child].key) break;
        heap_[i] = heap_[child];
        i = child;
      }
      heap_[i] = last;
    }
    return top;
  }
  void pushReady(void* target, Process* p) {
    if (readyCount() == ready_.size()) {
      std::vector<Entry> bigger(ready_.size() * 2);
      for (std::size_t i = 0; i < readyCount(); ++i) bigger[i] = ready_[(readyHead_ + i) & (ready_.size() - 1)];
      readyTail_ = readyCount();
      readyHead_ = 0;
      ready_.swap(bigger);
    }
    ready_[readyTail_ & (ready_.size() - 1)] = Entry{makeKey(now_, seq_++), target, p};
    ++readyTail_;
  }
  std::size_t readyCount() const { return readyTail_ - readyHead_; }
  bool popNext(Tick limit, Entry& out) {
    if (!heap_.empty() && heap_.front().time() <= now_) {
      out = heapPop();
      return true;
    }
    if (readyCount() != 0) {
      out = ready_[readyHead_ & (ready_.size() - 1)];
      ++readyHead_;
      if (readyHead_ == readyTail_) readyHead_ = readyTail_ = 0;
      return true;
    }
    if (heap_.empty() || heap_.front().time() > limit) return false;
    out = heapPop();
    now_ = out.time();
    return true;
  }
  void dispatch(const Entry& e) {
    ++events_;
    Process& p = *e.proc;
    current_ = &p;
    std::coroutine_handle<>::from_address(e.target).resume();
    current_ = nullptr;
    if (p.done_) {
      auto root = std::exchange(p.root_, {});
      root.destroy();
    }
  }

  Tick now_ = 0;
  std::uint64_t seq_ = 0;
  std::uint64_t events_ = 0;
  Process* current_ = nullptr;
  std::vector<Entry> heap_;
  std::vector<Entry> ready_;
  std::size_t readyHead_ = 0;
  std::size_t readyTail_ = 0;
  std::deque<std::unique_ptr<Process>> processes_;
};

}  // namespace vbim::baseline
