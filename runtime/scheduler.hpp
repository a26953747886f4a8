// The deterministic discrete-event scheduler: every cooperating thread of the model is a coroutine
// resumed here, in (time, lane, insertion order). Only the simulation thread touches it; model code
// never reads the wall clock. Style after emulator schedulers (Dolphin CoreTiming, ares cooperative
// threads): small, explicit, one time base.
//
// Lanes: a process belongs to one of two lanes, and at any one tick every entry of the first lane
// runs before any of the normal lane's. Within a lane the order is time, then insertion, exactly as
// if the other lane did not exist, so two models that share no simulated state (the player's run
// and its fault-free reference, issue #31) each see the same events in the same order whichever
// lane they are in; the lane decides only which of the two goes first at a tick they share.
#pragma once

#include <coroutine>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "runtime/clock.hpp"
#include "runtime/task.hpp"

namespace vbim {

class Event;

enum class Lane : std::uint8_t { First = 0, Normal = 1 };

// One spawned cooperating thread. Owned by the scheduler; handles stay valid for its lifetime.
class Process {
 public:
  const std::string& name() const { return name_; }
  bool done() const { return done_; }
  bool suspended() const { return suspended_; }
  // Total simulated time this process spent suspended from outside.
  Tick suspendedTotal() const { return suspendedTotal_; }
  Lane lane() const { return lane_; }

 private:
  friend class Scheduler;
  std::string name_;
  std::coroutine_handle<Task<void>::promise_type> root_;
  bool done_ = false;
  bool suspended_ = false;
  Lane lane_ = Lane::Normal;
  Tick suspendedSince_ = 0;
  Tick suspendedTotal_ = 0;
  std::vector<void*> deferred_;  // coroutine addresses whose wake-up fell inside a suspension
};

class Scheduler {
 public:
  Scheduler();
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  // Starts a process at the current time (after everything of its lane already due now). It goes in
  // the lane of the process that spawns it, or, spawned from outside any process, in the lane of
  // the innermost LaneScope (Lane::Normal without one).
  Process& spawn(std::string name, Task<void> task);

  // While it lives, processes spawned and events scheduled from outside any process go in `lane`
  // (e.g. around the construction and start of a model whose processes should go first at a tick).
  class LaneScope {
   public:
    LaneScope(Scheduler& s, Lane lane) : s_(s), saved_(s.outsideLane_) { s.outsideLane_ = lane; }
    ~LaneScope() { s_.outsideLane_ = saved_; }
    LaneScope(const LaneScope&) = delete;
    LaneScope& operator=(const LaneScope&) = delete;

   private:
    Scheduler& s_;
    Lane saved_;
  };

  Tick now() const { return now_; }
  // The process whose coroutine is running (null outside run()).
  Process* current() const { return current_; }
  // Number of wake-ups processed so far (the "model events" of the benchmarks).
  std::uint64_t eventsProcessed() const { return events_; }

  // Runs until no work is left. Returns the time of the last event.
  Tick run();
  // Runs every event with time <= t, then sets now() to t (if t is later). Events after t wait.
  void runUntil(Tick t);
  // True when nothing is scheduled (waiters on events or FIFOs do not count).
  bool idle() const { return heap_.empty() && readyCount() == 0; }

  // Suspends p from outside (fault injection): wake-ups that fall inside the suspension are held
  // and delivered, in order, when it is resumed. Suspending a suspended process is a no-op.
  void suspend(Process& p);
  void resume(Process& p);
  // Suspends p now and resumes it `duration` ticks later.
  void suspendFor(Process& p, Tick duration);

  // co_await sched.delay(t): resumes the caller t ticks from now (t >= 0; 0 yields to everything
  // else due now).
  // When the caller's wake-up would be the very next entry run anyway, it continues without
  // suspending (see continueAt): the same order and times, without a queue round trip.
  struct DelayAwaiter {
    Scheduler& s;
    Tick d;
    bool await_ready() const noexcept { return s.continueAt(s.now_ + d); }
    void await_suspend(std::coroutine_handle<> h) const { s.scheduleAt(s.now_ + d, h.address(), s.current_); }
    void await_resume() const noexcept {}
  };
  DelayAwaiter delay(Tick d) { return DelayAwaiter{*this, d < 0 ? 0 : d}; }
  // co_await sched.until(t): resumes the caller at absolute time t (or now, if t has passed).
  DelayAwaiter until(Tick t) { return DelayAwaiter{*this, t > now_ ? t - now_ : 0}; }

  // Low-level: wake coroutine `h` of process `p` now, after what is already due now in its lane.
  // Used by Event and Fifo.
  void wakeNow(std::coroutine_handle<> h, Process* p) { pushReady(h.address(), p); }
  // Low-level: notify `e` at absolute time t.
  void notifyAt(Event& e, Tick t);

 private:
  // An entry is one of: resume a coroutine (target = frame address, proc = owner), notify an event
  // (target = Event*, proc = null), or resume a suspended process (target = null, proc set).
  // The heap orders on one 128-bit key, (time << 64) | (lane << 63) | seq: times in the queue are
  // never negative, and seq never reaches 2^63.
  struct Entry {
    unsigned __int128 key;
    void* target;
    Process* proc;
    Tick time() const { return static_cast<Tick>(key >> 64); }
    unsigned lane() const { return static_cast<unsigned>(key >> 63) & 1u; }
  };
  static unsigned __int128 makeKey(Tick t, Lane lane, std::uint64_t seq) {
    return (static_cast<unsigned __int128>(t) << 64) | (static_cast<unsigned __int128>(lane) << 63) | seq;
  }
  // The lane of an entry for process p (or, for an event, of whoever schedules it).
  Lane laneOf(const Process* p) const {
    if (p != nullptr) return p->lane_;
    return current_ != nullptr ? current_->lane_ : outsideLane_;
  }
  // The key is passed by value: building an Entry on the stack and loading it back as one 128-bit
  // value stalls store forwarding.
  void heapPush(unsigned __int128 key, void* target, Process* p);
  Entry heapPop();
  // True (and time advanced to t, the wake-up counted) when the running process's wake-up at t
  // would be the next entry dispatched: nothing ready now, nothing in the queue at or before t, t
  // within the current run limit, the process not suspended.
  // At most kMaxInlineContinuations in a row, then one trip through the queue: a coroutine that
  // continues inline and then finishes a nested Task resumes its awaiter by symmetric transfer,
  // which is a tail call only when the compiler makes it one (GCC does not under ASan), so an
  // unbounded run of inline continuations could grow the host stack without end.
  bool continueAt(Tick t) {
    if (current_ == nullptr || readyCount() != 0 || t > limit_ || current_->suspended_) return false;
    if (!heap_.empty() && heap_.front().time() <= t) return false;
    if (++inlineRun_ > kMaxInlineContinuations) return false;
    now_ = t;
    ++seq_;
    ++events_;
    return true;
  }

  void scheduleAt(Tick t, void* target, Process* p);
  void pushReady(void* target, Process* p);
  // Entries due at now_, FIFO per lane (ring buffers, power-of-two sizes).
  struct ReadyRing {
    std::vector<Entry> slots = std::vector<Entry>(64);
    std::size_t head = 0;
    std::size_t tail = 0;
    std::size_t count() const { return tail - head; }
  };
  std::size_t readyCount() const { return ready_[0].count() + ready_[1].count(); }
  bool popNext(Tick limit, Entry& out);
  void dispatch(const Entry& e);
  void finishProcess(Process& p);

  static constexpr std::uint32_t kMaxInlineContinuations = 64;

  Tick now_ = 0;
  std::uint32_t inlineRun_ = 0;  // inline continuations since the last dispatch
  std::uint64_t seq_ = 0;
  std::uint64_t events_ = 0;
  Process* current_ = nullptr;
  Tick limit_ = 0;                   // the time run()/runUntil() stops at (entries after it wait)
  Lane outsideLane_ = Lane::Normal;  // LaneScope
  std::vector<Entry> heap_;          // future entries, min-heap on (time, lane, seq)
  ReadyRing ready_[2];               // by lane
  std::deque<std::unique_ptr<Process>> processes_;
};

}  // namespace vbim
