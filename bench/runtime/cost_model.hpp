// The model the scheduler-cost benchmark runs on each kernel (bench/runtime/cost_bench.cpp): the
// shape of runtime/shape_model.hpp without tracing or faults. A producer emits a token every
// 13.9 us into a channel of depth 8, a consumer takes 20 us per token, a 59.94 Hz vsync samples the
// consumer's count. Model events are counted by the model, not by the kernel, and the SystemC
// version (cost_systemc.cpp) counts the same ones: a producer period elapsed, a token accepted by
// the channel, a token taken, a token finished, a vsync. Kernel wake-ups differ between kernels
// (a blocked push is one wake-up here and a delta cycle plus a wake-up in SystemC); these do not.
#pragma once

#include <coroutine>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "runtime/clock.hpp"
#include "runtime/task.hpp"
#include "runtime/vsync.hpp"

namespace vbim::bench {

inline constexpr Tick kProducerPeriod = fromNs(13'900);
inline constexpr Tick kConsumerCost = fromUs(20);
inline constexpr std::size_t kDepth = 8;

struct CostCounts {
  std::uint64_t events = 0;  // model events (above)
  std::uint64_t consumed = 0;
};

// A bounded channel with at most one blocked pusher and one blocked popper (one producer, one
// consumer), woken through the scheduler at the current time, as runtime/fifo.hpp does.
template <class S>
class Channel {
 public:
  explicit Channel(S& s) : s_(s) {}

  struct PushAwaiter {
    Channel& c;
    std::uint64_t v;
    bool await_ready() {
      if (c.count_ == kDepth) return false;
      c.put(v);
      return true;
    }
    void await_suspend(std::coroutine_handle<> h) {
      c.pusher_ = h;
      c.pusherProc_ = c.s_.current();
      c.pending_ = v;
    }
    void await_resume() const noexcept {}
  };
  struct PopAwaiter {
    Channel& c;
    bool await_ready() const { return c.count_ != 0; }
    void await_suspend(std::coroutine_handle<> h) {
      c.popper_ = h;
      c.popperProc_ = c.s_.current();
    }
    std::uint64_t await_resume() { return c.take(); }
  };
  PushAwaiter push(std::uint64_t v) { return PushAwaiter{*this, v}; }
  PopAwaiter pop() { return PopAwaiter{*this}; }

 private:
  void put(std::uint64_t v) {
    slots_[(head_ + count_) % kDepth] = v;
    ++count_;
    if (popper_) s_.wakeNow(std::exchange(popper_, {}), popperProc_);
  }
  std::uint64_t take() {
    const std::uint64_t v = slots_[head_];
    head_ = (head_ + 1) % kDepth;
    --count_;
    if (pusher_) {
      put(pending_);
      s_.wakeNow(std::exchange(pusher_, {}), pusherProc_);
    }
    return v;
  }

  S& s_;
  std::uint64_t slots_[kDepth] = {};
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  std::coroutine_handle<> pusher_{}, popper_{};
  decltype(std::declval<S&>().current()) pusherProc_ = nullptr, popperProc_ = nullptr;
  std::uint64_t pending_ = 0;
};

template <class S>
Task<void> costProducer(S& s, Channel<S>& ch, CostCounts& c) {
  for (std::uint64_t n = 0;; ++n) {
    co_await s.delay(kProducerPeriod);
    ++c.events;
    co_await ch.push(n);
    ++c.events;
  }
}

template <class S>
Task<void> costConsumer(S& s, Channel<S>& ch, CostCounts& c) {
  for (;;) {
    const std::uint64_t token = co_await ch.pop();
    ++c.events;
    co_await s.delay(kConsumerCost);
    ++c.events;
    c.consumed += token == c.consumed ? 1 : 0;  // tokens arrive in order
  }
}

template <class S>
Task<void> costVsync(S& s, CostCounts& c) {
  const VsyncClock clock(kNtsc);
  for (std::int64_t n = 1;; ++n) {
    co_await s.until(clock.time(n));
    ++c.events;
  }
}

// Runs the model for `duration` of simulated time on a fresh scheduler of type S.
template <class S>
CostCounts runCostModel(Tick duration) {
  S s;
  Channel<S> ch(s);
  CostCounts c;
  s.spawn("producer", costProducer(s, ch, c));
  s.spawn("consumer", costConsumer(s, ch, c));
  s.spawn("vsync", costVsync(s, c));
  s.runUntil(duration);
  return c;
}

}  // namespace vbim::bench
