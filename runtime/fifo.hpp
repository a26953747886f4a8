// Fifo<T>: a bounded first-in first-out channel between cooperating threads.
// `co_await f.push(v)` blocks while the FIFO is full; `T v = co_await f.pop()` blocks while it is
// empty. Blocked pushers and poppers are served strictly in arrival order, and a value is handed
// over directly to a waiting popper, so back-pressure is exact and deterministic.
#pragma once

#include <cassert>
#include <coroutine>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>

#include "runtime/scheduler.hpp"

namespace vbim {

template <class T>
class Fifo {
 public:
  Fifo(Scheduler& s, std::size_t depth, std::string name = {}) : s_(s), depth_(depth), name_(std::move(name)) {
    assert(depth > 0);
  }
  Fifo(const Fifo&) = delete;
  Fifo& operator=(const Fifo&) = delete;

  struct PushAwaiter {
    Fifo& f;
    T value;
    std::coroutine_handle<> h{};
    Process* p = nullptr;
    bool await_ready() {
      if (f.pushers_.empty() && f.items_.size() < f.depth_) {
        f.put(std::move(value));
        return true;
      }
      return false;
    }
    void await_suspend(std::coroutine_handle<> hh) {
      h = hh;
      p = f.s_.current();
      f.pushers_.push_back(this);
    }
    void await_resume() const noexcept {}
  };
  struct PopAwaiter {
    Fifo& f;
    std::optional<T> slot{};
    std::coroutine_handle<> h{};
    Process* p = nullptr;
    bool await_ready() {
      if (f.poppers_.empty() && !f.items_.empty()) {
        slot.emplace(f.take());
        return true;
      }
      return false;
    }
    void await_suspend(std::coroutine_handle<> hh) {
      h = hh;
      p = f.s_.current();
      f.poppers_.push_back(this);
    }
    T await_resume() { return std::move(*slot); }
  };

  PushAwaiter push(T v) { return PushAwaiter{*this, std::move(v)}; }
  PopAwaiter pop() { return PopAwaiter{*this}; }

  // Non-blocking variants for code outside a coroutine.
  bool tryPush(T v) {
    if (!pushers_.empty() || items_.size() >= depth_) return false;
    put(std::move(v));
    return true;
  }
  std::optional<T> tryPop() {
    if (!poppers_.empty() || items_.empty()) return std::nullopt;
    return take();
  }

  std::size_t size() const { return items_.size(); }
  std::size_t depth() const { return depth_; }
  bool full() const { return items_.size() >= depth_; }
  bool empty() const { return items_.empty(); }
  std::size_t blockedPushers() const { return pushers_.size(); }
  std::size_t blockedPoppers() const { return poppers_.size(); }
  const std::string& name() const { return name_; }

 private:
  // Adds a value: straight to the first waiting popper if there is one.
  void put(T v) {
    if (!poppers_.empty()) {
      PopAwaiter* w = poppers_.front();
      poppers_.pop_front();
      w->slot.emplace(std::move(v));
      s_.wakeNow(w->h, w->p);
      return;
    }
    items_.push_back(std::move(v));
  }
  // Removes the oldest value and lets the first waiting pusher in.
  T take() {
    T v = std::move(items_.front());
    items_.pop_front();
    if (!pushers_.empty()) {
      PushAwaiter* w = pushers_.front();
      pushers_.pop_front();
      items_.push_back(std::move(w->value));
      s_.wakeNow(w->h, w->p);
    }
    return v;
  }

  Scheduler& s_;
  std::size_t depth_;
  std::string name_;
  std::deque<T> items_;
  std::deque<PushAwaiter*> pushers_;
  std::deque<PopAwaiter*> poppers_;
};

}  // namespace vbim
