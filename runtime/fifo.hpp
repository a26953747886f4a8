// Fifo<T>: a bounded first-in first-out channel between cooperating threads.
// `co_await f.push(v)` blocks while the FIFO is full; `T v = co_await f.pop()` blocks while it is
// empty. Blocked pushers and poppers are served strictly in arrival order, and a value is handed
// over directly to a waiting popper, so back-pressure is exact and deterministic.
#pragma once

#include <cassert>
#include <coroutine>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/scheduler.hpp"

namespace vbim {

template <class T>
class Fifo {
 public:
  Fifo(Scheduler& s, std::size_t depth, std::string name = {})
      : s_(s), depth_(depth), name_(std::move(name)), slots_(depth) {
    assert(depth > 0);
  }
  Fifo(const Fifo&) = delete;
  Fifo& operator=(const Fifo&) = delete;

  struct PushAwaiter {
    Fifo& f;
    T value;
    std::coroutine_handle<> h{};
    Process* p = nullptr;
    PushAwaiter* next = nullptr;
    bool await_ready() {
      if (f.pushers_.empty() && f.count_ < f.depth_) {
        f.put(std::move(value));
        return true;
      }
      return false;
    }
    void await_suspend(std::coroutine_handle<> hh) {
      h = hh;
      p = f.s_.current();
      f.pushers_.pushBack(this);
    }
    void await_resume() const noexcept {}
  };
  struct PopAwaiter {
    Fifo& f;
    std::optional<T> slot{};
    std::coroutine_handle<> h{};
    Process* p = nullptr;
    PopAwaiter* next = nullptr;
    bool await_ready() {
      if (f.poppers_.empty() && f.count_ != 0) {
        slot.emplace(f.take());
        return true;
      }
      return false;
    }
    void await_suspend(std::coroutine_handle<> hh) {
      h = hh;
      p = f.s_.current();
      f.poppers_.pushBack(this);
    }
    T await_resume() { return std::move(*slot); }
  };

  PushAwaiter push(T v) { return PushAwaiter{*this, std::move(v)}; }
  PopAwaiter pop() { return PopAwaiter{*this}; }

  // Non-blocking variants for code outside a coroutine.
  bool tryPush(T v) {
    if (!pushers_.empty() || count_ >= depth_) return false;
    put(std::move(v));
    return true;
  }
  std::optional<T> tryPop() {
    if (!poppers_.empty() || count_ == 0) return std::nullopt;
    return take();
  }

  std::size_t size() const { return count_; }
  std::size_t depth() const { return depth_; }
  bool full() const { return count_ >= depth_; }
  bool empty() const { return count_ == 0; }
  std::size_t blockedPushers() const { return pushers_.size; }
  std::size_t blockedPoppers() const { return poppers_.size; }
  const std::string& name() const { return name_; }

 private:
  // Adds a value: straight to the first waiting popper if there is one.
  void put(T v) {
    if (!poppers_.empty()) {
      PopAwaiter* w = poppers_.popFront();
      w->slot.emplace(std::move(v));
      s_.wakeNow(w->h, w->p);
      return;
    }
    std::size_t tail = head_ + count_;
    if (tail >= depth_) tail -= depth_;
    slots_[tail] = std::move(v);
    ++count_;
  }
  // Removes the oldest value and lets the first waiting pusher in.
  T take() {
    T v = std::move(slots_[head_]);
    if (++head_ == depth_) head_ = 0;
    --count_;
    if (!pushers_.empty()) {
      PushAwaiter* w = pushers_.popFront();
      put(std::move(w->value));
      s_.wakeNow(w->h, w->p);
    }
    return v;
  }

  // Waiters queue through a pointer in their awaiter (which lives in the waiting coroutine's frame),
  // so blocking allocates nothing.
  template <class W>
  struct WaitQueue {
    W* head = nullptr;
    W* tail = nullptr;
    std::size_t size = 0;
    bool empty() const { return head == nullptr; }
    void pushBack(W* w) {
      w->next = nullptr;
      (tail != nullptr ? tail->next : head) = w;
      tail = w;
      ++size;
    }
    W* popFront() {
      W* w = head;
      head = w->next;
      if (head == nullptr) tail = nullptr;
      --size;
      return w;
    }
  };

  Scheduler& s_;
  std::size_t depth_;
  std::string name_;
  std::vector<T> slots_;  // ring of depth_ values
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  WaitQueue<PushAwaiter> pushers_;
  WaitQueue<PopAwaiter> poppers_;
};

}  // namespace vbim
