// How fast the IOP model runs: simulated seconds of streaming per host second, for a clean disc
// and for one with random stalls and errors. Reported as counters (sim_s_per_host_s) and the ratio
// of the faulty run to the clean one.
#include <benchmark/benchmark.h>

#include <vector>

#include "config/fault_plan_toml.hpp"
#include "iop/drive.hpp"
#include "iop/fault_plan.hpp"
#include "iop/memory_disc.hpp"
#include "iop/sif.hpp"
#include "iop/stream_ring.hpp"

namespace {

using namespace vbim;
using namespace vbim::iop;

Task<void> startRing(StreamRing& ring) {
  (void)co_await ring.start(100'000);
}

Task<void> reader(Scheduler& s, StreamRing& ring) {
  std::vector<std::uint8_t> buf(16 * kSectorBytes);
  for (;;) {
    co_await s.delay(fromUs(16'683));  // one NTSC field
    (void)co_await ring.read(16, buf);
  }
}

void streamSeconds(benchmark::State& state, bool faults) {
  const Tick simulated = fromMs(60'000);
  for (auto _ : state) {
    Scheduler s;
    MemoryDisc disc(2'298'496);
    disc.addPatternFile("/S.PSS", 100'000, 200'000);
    IopParams p;
    Drive drive(s, disc, p.drive, Rng(1));
    SifChannel sif(s, p.sif);
    StreamRing ring(s, drive, sif, p.ring);
    if (faults) {
      applyFaults(s, drive,
                  config::parseFaultPlan("[[fault]]\nkind = \"random_stall\"\nfrom = \"0s\"\nduration = \"60s\"\n"
                                         "mean_interval = \"2s\"\nstall = \"200ms\"\n"
                                         "[[fault]]\nkind = \"random_error\"\nfrom = \"0s\"\nduration = \"60s\"\n"
                                         "per_million = 1000\n",
                                         "bench"),
                  Rng(2));
    }
    s.spawn("start", startRing(ring));
    s.spawn("ee", reader(s, ring));
    s.runUntil(simulated);
    benchmark::DoNotOptimize(ring.stats().underruns);
  }
  state.counters["sim_s_per_host_s"] =
      benchmark::Counter(toSeconds(simulated) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_StreamClean(benchmark::State& state) {
  streamSeconds(state, false);
}
void BM_StreamFaulty(benchmark::State& state) {
  streamSeconds(state, true);
}
BENCHMARK(BM_StreamClean)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StreamFaulty)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
