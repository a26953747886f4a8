#include "runtime/shape_model.hpp"

#include <array>
#include <memory>

#include "runtime/fifo.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim {

namespace {

struct Model {
  Scheduler sched;
  Fifo<std::uint64_t> fifo;
  ShapeModelSettings cfg;
  ShapeModelResult result;
  Tracer* tracer;
  Tracer::TrackId producerTrack = 0, consumerTrack = 0, vsyncTrack = 0;
  Tracer::CounterId fifoCounter = 0, consumedCounter = 0;

  Model(const ShapeModelSettings& s, Tracer* t) : fifo(sched, s.fifoDepth, "tokens"), cfg(s), tracer(t) {
    if (tracer != nullptr) {
      producerTrack = tracer->track("producer");
      consumerTrack = tracer->track("consumer");
      vsyncTrack = tracer->track("vsync");
      fifoCounter = tracer->counter("fifo.occupancy");
      consumedCounter = tracer->counter("consumer.count");
    }
  }
  bool tracing() const { return tracer != nullptr && tracer->enabled(); }
};

Task<void> producer(Model& m) {
  for (std::uint64_t n = 0;; ++n) {
    co_await m.sched.delay(m.cfg.producerPeriod);
    if (m.fifo.full()) ++m.result.producerBlocked;
    co_await m.fifo.push(n);
    ++m.result.produced;
  }
}

Task<void> consumer(Model& m) {
  for (;;) {
    const std::uint64_t token = co_await m.fifo.pop();
    const Tick start = m.sched.now();
    co_await m.sched.delay(m.cfg.consumerCost);
    m.result.consumed += (token == m.result.consumed) ? 1 : 0;  // tokens arrive in order
    if (m.tracing()) m.tracer->span(m.consumerTrack, start, m.sched.now(), "token");
  }
}

// A deterministic stand-in for pixel work: each row of a 64x64 frame is hashed on the pool.
std::uint64_t frameRowHash(std::uint64_t frame, std::size_t row) {
  std::uint64_t h = 0xcbf29ce484222325ULL ^ (frame * 0x9E3779B97F4A7C15ULL);
  for (std::size_t x = 0; x < 64; ++x) h = (h ^ ((frame + row * 64 + x) & 0xFF)) * 0x100000001b3ULL;
  return h;
}

Task<void> vsync(Model& m) {
  const VsyncClock clock(m.cfg.vsync);
  std::uint64_t lastConsumed = 0;
  for (std::int64_t n = 1;; ++n) {
    co_await m.sched.until(clock.time(n));
    ++m.result.vsyncs;
    if (m.result.consumed == lastConsumed) ++m.result.starvedVsyncs;
    lastConsumed = m.result.consumed;
    if (m.tracing()) {
      m.tracer->instant(m.vsyncTrack, m.sched.now(), "vsync");
      m.tracer->value(m.consumedCounter, m.sched.now(), static_cast<std::int64_t>(m.result.consumed));
      // Occupancy sampled once per vsync: per-token samples would toggle 7/8 millions of times.
      m.tracer->value(m.fifoCounter, m.sched.now(), static_cast<std::int64_t>(m.fifo.size()));
    }
    if (m.cfg.pool != nullptr) {
      // Host threads compute now; the model takes the result 1 ms of simulated time later.
      auto rows = std::make_shared<std::array<std::uint64_t, 64>>();
      const std::uint64_t frame = lastConsumed;
      auto batch = m.cfg.pool->submit(64, [rows, frame](std::size_t r) { (*rows)[r] = frameRowHash(frame, r); });
      co_await m.sched.delay(fromMs(1));
      batch->wait();
      for (std::uint64_t h : *rows) m.result.frameChecksum = (m.result.frameChecksum ^ h) * 0x100000001b3ULL;
    }
  }
}

Task<void> stallFault(Model& m, Process& victim) {
  co_await m.sched.until(m.cfg.stallAt);
  if (m.tracing()) m.tracer->span(m.producerTrack, m.sched.now(), m.sched.now() + m.cfg.stallFor, "stall");
  m.sched.suspendFor(victim, m.cfg.stallFor);
}

}  // namespace

ShapeModelResult runShapeModel(const ShapeModelSettings& settings, Tracer* tracer) {
  Model m(settings, tracer);
  Process& prod = m.sched.spawn("producer", producer(m));
  m.sched.spawn("consumer", consumer(m));
  m.sched.spawn("vsync", vsync(m));
  if (settings.stallFor > 0) m.sched.spawn("fault", stallFault(m, prod));
  m.sched.runUntil(settings.duration);
  m.result.events = m.sched.eventsProcessed();
  m.result.producerSuspended = prod.suspendedTotal();
  m.result.end = m.sched.now();
  return m.result;
}

}  // namespace vbim
