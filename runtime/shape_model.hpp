// The kernel's exercise model: a producer emits a token every 13.9 us into a FIFO of depth 8, a
// consumer takes 20 us per token, a 59.94 Hz vsync samples the consumer's count, and an injected
// fault suspends the producer for 500 ms at 3 s. It has the shape of the real pipeline (drive ->
// ring -> decoder, observed at vsync) without its detail, and serves the kernel's benchmark, its
// determinism tests, and `vbim demo` until the full pipeline exists.
#pragma once

#include <cstdint>

#include "runtime/clock.hpp"
#include "runtime/vsync.hpp"

namespace vbim {

class Tracer;
class WorkerPool;

struct ShapeModelSettings {
  Tick producerPeriod = fromNs(13'900);
  Tick consumerCost = fromUs(20);
  std::size_t fifoDepth = 8;
  VsyncRate vsync = kNtsc;
  Tick stallAt = fromMs(3'000);
  Tick stallFor = fromMs(500);
  Tick duration = fromMs(60'000);
  // Optional host threads: at each vsync a checksum of a 64x64 "frame" derived from the
  // consumer's count is computed on the pool and taken 1 ms of simulated time later.
  WorkerPool* pool = nullptr;
};

struct ShapeModelResult {
  std::uint64_t produced = 0;
  std::uint64_t consumed = 0;
  std::uint64_t vsyncs = 0;
  std::uint64_t starvedVsyncs = 0;    // vsyncs at which the consumer made no progress since the last
  std::uint64_t producerBlocked = 0;  // pushes that found the FIFO full
  std::uint64_t events = 0;           // scheduler wake-ups
  std::uint64_t frameChecksum = 0;    // combined pool results (0 without a pool)
  Tick producerSuspended = 0;
  Tick end = 0;
};

ShapeModelResult runShapeModel(const ShapeModelSettings& settings, Tracer* tracer = nullptr);

}  // namespace vbim
