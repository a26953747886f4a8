// SerialUnit: hardware that does one job at a time on the simulated clock, for several clients
// (the GS: one GIF and one drawing engine, fed by the lightmap and the sky presenters). A client
// holds it from acquire() to release(); others wait, and get it in the order they asked.
//
//   co_await gs.acquire();
//   co_await sched.delay(work);
//   gs.release();
#pragma once

#include <cstdint>

#include "runtime/event.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/task.hpp"

namespace vbim {

class SerialUnit {
 public:
  explicit SerialUnit(Scheduler& s) : s_(s), freed_(s) {}
  SerialUnit(const SerialUnit&) = delete;
  SerialUnit& operator=(const SerialUnit&) = delete;

  // Returns once this client holds the unit; waiting time is counted in waited().
  Task<void> acquire() {
    const Tick asked = s_.now();
    // A ticket per request: release() hands the unit to the oldest ticket still waiting, so a
    // client that asks while others wait cannot take it first (Event wakes every waiter).
    const std::uint64_t ticket = nextTicket_++;
    while (busy_ || ticket != serving_) co_await freed_.wait();
    busy_ = true;
    ++serving_;
    waited_ += s_.now() - asked;
  }
  void release() {
    busy_ = false;
    freed_.notify();
  }

  bool busy() const { return busy_; }
  Tick waited() const { return waited_; }  // all clients' time spent waiting for the unit

 private:
  Scheduler& s_;
  Event freed_;
  bool busy_ = false;
  std::uint64_t nextTicket_ = 0;
  std::uint64_t serving_ = 0;  // the ticket whose turn it is
  Tick waited_ = 0;
};

}  // namespace vbim
