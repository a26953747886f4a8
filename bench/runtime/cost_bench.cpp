// Scheduler cost per model event (issue #17): the same model (cost_model.hpp) on the kernel's
// scheduler, on the scheduler it replaced (baseline_scheduler.hpp) and, when libsystemc-dev is
// installed, on SystemC 2.3.4, each counting the same model events. Reports ns per model event and,
// at the end, the ratios against the kernel's scheduler.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "bench/runtime/baseline_scheduler.hpp"
#include "bench/runtime/cost_model.hpp"
#include "runtime/scheduler.hpp"
#if VBIM_HAVE_SYSTEMC
#include "bench/runtime/cost_systemc.hpp"
#endif

namespace {

constexpr double kSeconds = 10.0;  // simulated per iteration

std::map<std::string, double>& nsPerEvent() {
  static std::map<std::string, double> m;
  return m;
}

void report(benchmark::State& state, const std::string& name, std::uint64_t events) {
  state.counters["model_events/s"] = benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
  state.counters["events/iter"] = static_cast<double>(events) / static_cast<double>(state.iterations());
  // The benchmark's own CPU time per iteration, over the events of one iteration.
  state.counters["ns/event"] =
      benchmark::Counter(static_cast<double>(events) / 1e9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  (void)name;
}

template <class S>
void kernelCost(benchmark::State& state, const std::string& name) {
  std::uint64_t events = 0;
  for (auto _ : state) {
    const auto c = vbim::bench::runCostModel<S>(vbim::fromMs(static_cast<std::int64_t>(kSeconds * 1000)));
    events += c.events;
    benchmark::DoNotOptimize(c.consumed);
  }
  report(state, name, events);
}

#if VBIM_HAVE_SYSTEMC
void systemcCost(benchmark::State& state) {
  std::uint64_t events = 0;
  for (auto _ : state) {
    const auto r = vbim::bench::runSystemCCostModel(kSeconds);
    events += r.events;
    benchmark::DoNotOptimize(r.consumed);
  }
  report(state, "systemc", events);
}
#endif

// Collects ns/event per benchmark to print the ratios after the run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      // One figure per benchmark: the median when repeated, the single run otherwise.
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      const auto it = r.counters.find("ns/event");
      if (it != r.counters.end()) nsPerEvent()[r.run_name.function_name] = it->second;
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  benchmark::RegisterBenchmark("BM_Kernel/current", kernelCost<vbim::Scheduler>, std::string("current"))
      ->Unit(benchmark::kMillisecond)
      ->MinTime(1.0);
  benchmark::RegisterBenchmark("BM_Kernel/baseline", kernelCost<vbim::baseline::Scheduler>, std::string("baseline"))
      ->Unit(benchmark::kMillisecond)
      ->MinTime(1.0);
#if VBIM_HAVE_SYSTEMC
  benchmark::RegisterBenchmark("BM_SystemC", systemcCost)->Unit(benchmark::kMillisecond)->MinTime(1.0);
#else
  std::puts("SystemC comparison skipped: libsystemc-dev is not installed (scripts/setup.sh --with-bench)");
#endif
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  const auto& m = nsPerEvent();
  const auto cur = m.find("BM_Kernel/current");
  if (cur == m.end() || cur->second <= 0) return 0;
  for (const auto& [name, ns] : m) {
    if (name != cur->first)
      std::printf("%s / BM_Kernel/current: %.2fx the cost per model event\n", name.c_str(), ns / cur->second);
  }
  return 0;
}
