// Kernel speed: the model shape of issue #2 (producer every 13.9 us -> FIFO depth 8 -> consumer
// 20 us/token, 59.94 Hz vsync reading the consumer's count, 500 ms producer stall at 3 s, 60
// simulated seconds), reported as model events per wall second. Target: >= 50 M events/s on one
// core (a comparable coroutine prototype: 62 M/s; SystemC 2.3.4: 9.1 M/s on this machine).
#include <benchmark/benchmark.h>

#include "runtime/shape_model.hpp"
#include "runtime/trace.hpp"

namespace {

void BM_ShapeModel60s(benchmark::State& state) {
  vbim::ShapeModelSettings s;
  std::uint64_t events = 0;
  for (auto _ : state) {
    const auto r = vbim::runShapeModel(s);
    events += r.events;
    benchmark::DoNotOptimize(r.consumed);
  }
  state.counters["events/s"] = benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
  state.counters["sim_s/wall_s"] =
      benchmark::Counter(60.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ShapeModel60s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The same run with tracing on: what recording every span and counter costs.
void BM_ShapeModel60sTraced(benchmark::State& state) {
  vbim::ShapeModelSettings s;
  std::uint64_t events = 0;
  for (auto _ : state) {
    vbim::Tracer t;
    const auto r = vbim::runShapeModel(s, &t);
    events += r.events;
    benchmark::DoNotOptimize(t.spanCount());
  }
  state.counters["events/s"] = benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ShapeModel60sTraced)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
