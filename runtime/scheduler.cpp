#include "runtime/scheduler.hpp"

#include <algorithm>
#include <stdexcept>

#include "runtime/event.hpp"

namespace vbim {

Scheduler::Scheduler() = default;

Scheduler::~Scheduler() {
  // Frames of unfinished processes are destroyed with the scheduler. Nested Task frames are owned
  // by the frames that await them and go with them.
  for (auto& p : processes_) {
    if (p->root_) p->root_.destroy();
  }
}

Process& Scheduler::spawn(std::string name, Task<void> task) {
  auto proc = std::make_unique<Process>();
  proc->name_ = std::move(name);
  proc->root_ = task.release();
  proc->root_.promise().rootDone = &proc->done_;
  proc->lane_ = laneOf(nullptr);
  Process& p = *proc;
  processes_.push_back(std::move(proc));
  pushReady(p.root_.address(), &p);
  return p;
}

void Scheduler::scheduleAt(Tick t, void* target, Process* p) {
  if (t <= now_) {
    pushReady(target, p);
    return;
  }
  heapPush(makeKey(t, laneOf(p), seq_++), target, p);
}

// A binary min-heap with hole-based sifting, the kernel's hottest path after direct continuation
// (see continueAt). The player keeps a few dozen entries queued; a 4-ary heap measured no better
// there (fewer levels, but more compares per level).
void Scheduler::heapPush(unsigned __int128 key, void* target, Process* p) {
  heap_.emplace_back();
  std::size_t i = heap_.size() - 1;
  while (i > 0) {
    const std::size_t parent = (i - 1) / 2;
    if (heap_[parent].key <= key) break;
    heap_[i] = heap_[parent];
    i = parent;
  }
  heap_[i] = Entry{key, target, p};
}

Scheduler::Entry Scheduler::heapPop() {
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

void Scheduler::pushReady(void* target, Process* p) {
  const Lane lane = laneOf(p);
  ReadyRing& r = ready_[static_cast<unsigned>(lane)];
  if (r.count() == r.slots.size()) {
    // Grow the ring, keeping FIFO order.
    std::vector<Entry> bigger(r.slots.size() * 2);
    for (std::size_t i = 0; i < r.count(); ++i) bigger[i] = r.slots[(r.head + i) & (r.slots.size() - 1)];
    r.tail = r.count();
    r.head = 0;
    r.slots.swap(bigger);
  }
  r.slots[r.tail & (r.slots.size() - 1)] = Entry{makeKey(now_, lane, seq_++), target, p};
  ++r.tail;
}

void Scheduler::notifyAt(Event& e, Tick t) {
  scheduleAt(t, &e, nullptr);
}

// Entries of a lane already in the heap at time now_ were scheduled before time reached now_, so
// they come before anything of that lane made ready at now_: (time, lane, insertion order) holds
// without comparing sequences. The heap's front at now_ is of the first lane if any entry there is;
// one of the normal lane waits only for the first lane's ready entries.
bool Scheduler::popNext(Tick limit, Entry& out) {
  ReadyRing& first = ready_[0];
  if (!heap_.empty() && heap_.front().time() <= now_ && (first.count() == 0 || heap_.front().lane() == 0)) {
    out = heapPop();
    return true;
  }
  for (ReadyRing& r : ready_) {
    if (r.count() != 0) {
      out = r.slots[r.head & (r.slots.size() - 1)];
      ++r.head;
      if (r.head == r.tail) r.head = r.tail = 0;
      return true;
    }
  }
  if (heap_.empty() || heap_.front().time() > limit) return false;
  out = heapPop();
  now_ = out.time();
  return true;
}

void Scheduler::dispatch(const Entry& e) {
  ++events_;
  if (e.proc == nullptr) {
    static_cast<Event*>(e.target)->notify();
    return;
  }
  Process& p = *e.proc;
  if (e.target == nullptr) {
    resume(p);
    return;
  }
  if (p.suspended_) {
    p.deferred_.push_back(e.target);
    return;
  }
  current_ = &p;
  inlineRun_ = 0;
  std::coroutine_handle<>::from_address(e.target).resume();
  current_ = nullptr;
  if (p.done_) finishProcess(p);
}

void Scheduler::finishProcess(Process& p) {
  auto root = std::exchange(p.root_, {});
  std::exception_ptr err = root.promise().error;
  root.destroy();
  if (err) {
    try {
      std::rethrow_exception(err);
    } catch (const std::exception& ex) {
      throw std::runtime_error("process '" + p.name_ + "' failed at tick " + std::to_string(now_) + ": " + ex.what());
    }
  }
}

Tick Scheduler::run() {
  limit_ = kNever;
  Entry e;
  while (popNext(kNever, e)) dispatch(e);
  return now_;
}

void Scheduler::runUntil(Tick t) {
  limit_ = t;
  Entry e;
  while (popNext(t, e)) dispatch(e);
  if (t > now_) now_ = t;
}

void Scheduler::suspend(Process& p) {
  if (p.suspended_ || p.done_) return;
  p.suspended_ = true;
  p.suspendedSince_ = now_;
}

void Scheduler::resume(Process& p) {
  if (!p.suspended_) return;
  p.suspended_ = false;
  p.suspendedTotal_ += now_ - p.suspendedSince_;
  std::vector<void*> held;
  held.swap(p.deferred_);
  for (void* target : held) pushReady(target, &p);
}

void Scheduler::suspendFor(Process& p, Tick duration) {
  suspend(p);
  scheduleAt(now_ + std::max<Tick>(duration, 0), nullptr, &p);
}

}  // namespace vbim
