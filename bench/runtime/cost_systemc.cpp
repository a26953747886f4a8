#include "bench/runtime/cost_systemc.hpp"

#include <systemc>

#include "runtime/clock.hpp"
#include "runtime/vsync.hpp"

// libsystemc's own main() calls sc_main; the benchmark has its own main, but the symbol must exist.
int sc_main(int /*argc*/, char* /*argv*/[]) {
  return 0;
}

namespace vbim::bench {
namespace {

SC_MODULE(CostModule) {
  sc_core::sc_fifo<std::uint64_t> fifo{"tokens", 8};
  std::uint64_t events = 0;
  std::uint64_t consumed = 0;

  SC_CTOR(CostModule) {
    SC_THREAD(producer);
    SC_THREAD(consumer);
    SC_THREAD(vsync);
  }

  void producer() {
    for (std::uint64_t n = 0;; ++n) {
      wait(13'900, sc_core::SC_NS);
      ++events;
      fifo.write(n);
      ++events;
    }
  }
  void consumer() {
    for (;;) {
      std::uint64_t token = 0;
      fifo.read(token);
      ++events;
      wait(20, sc_core::SC_US);
      ++events;
      consumed += token == consumed ? 1 : 0;
    }
  }
  void vsync() {
    // The same vsync instants as runtime/vsync.hpp, rounded to SystemC's 1 ps resolution.
    const VsyncClock clock(kNtsc);
    for (std::int64_t n = 1;; ++n) {
      // Resolution units (ps, SystemC's default) since time 0: integer, floor as runtime/vsync.hpp.
      const auto ps = static_cast<sc_dt::uint64>(static_cast<__int128>(clock.time(n)) * 1'000'000'000'000 / kBusHz);
      wait(sc_core::sc_time::from_value(ps) - sc_core::sc_time_stamp());
      ++events;
    }
  }
};

}  // namespace

SystemCRun runSystemCCostModel(double seconds) {
  static CostModule* model = new CostModule("cost");  // lives as long as the SystemC kernel
  const std::uint64_t events = model->events;
  const std::uint64_t consumed = model->consumed;
  sc_core::sc_start(sc_core::sc_time(seconds, sc_core::SC_SEC));
  return SystemCRun{model->events - events, model->consumed - consumed};
}

}  // namespace vbim::bench
