// The scheduler-cost model of cost_model.hpp on SystemC 2.3.4 (SC_THREADs, an sc_fifo of depth 8,
// wait(time)), counting the same model events. SystemC elaborates once per process, so the model
// is built on the first call and each call simulates `seconds` more.
#pragma once

#include <cstdint>

namespace vbim::bench {

struct SystemCRun {
  std::uint64_t events = 0;
  std::uint64_t consumed = 0;
};

SystemCRun runSystemCCostModel(double seconds);

}  // namespace vbim::bench
