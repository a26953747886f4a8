// Event: a coroutine waits with `co_await ev.wait()`; notify() wakes every current waiter at the
// current time, in the order they started waiting. A notify with no waiter is not remembered (as
// in SystemC); use a Fifo or a counter for state that must persist.
#pragma once

#include <coroutine>
#include <utility>
#include <vector>

#include "runtime/scheduler.hpp"

namespace vbim {

class Event {
 public:
  explicit Event(Scheduler& s) : s_(s) {}
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;

  struct Awaiter {
    Event& e;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> h) { e.waiters_.push_back({h, e.s_.current()}); }
    void await_resume() const noexcept {}
  };
  Awaiter wait() { return Awaiter{*this}; }

  void notify() {
    if (waiters_.empty()) return;
    // Swap out first: a woken waiter may wait again before the others run.
    std::vector<Waiter> woken;
    woken.swap(waiters_);
    for (const Waiter& w : woken) s_.wakeNow(w.h, w.p);
  }
  // Notifies at absolute time t (now if t has passed).
  void notifyAt(Tick t) { s_.notifyAt(*this, t); }
  void notifyAfter(Tick d) { s_.notifyAt(*this, s_.now() + d); }

  bool hasWaiters() const { return !waiters_.empty(); }
  Scheduler& scheduler() const { return s_; }

 private:
  struct Waiter {
    std::coroutine_handle<> h;
    Process* p;
  };
  Scheduler& s_;
  std::vector<Waiter> waiters_;
};

}  // namespace vbim
