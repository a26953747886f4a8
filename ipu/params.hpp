// Every timing constant of the IPU model, registered under the prefix "ipu." in the platform
// config. Defaults and their reasoning: docs/timing/ipu.md and
// docs/hardware.md#ipu-decode-cost.
#pragma once

#include <cstdint>

#include "runtime/params.hpp"

namespace vbim::ipu {

struct IpuTimingParams {
  std::int64_t mbBaseCycles = 400;         // per macroblock, VLD + IQ + IDCT fixed part
  std::int64_t mbCyclesPerBit = 1;         // per input bit of the macroblock
  std::int64_t cscCyclesPerMb = 256;       // colour conversion, 1 pixel per cycle
  std::int64_t commandStartCycles = 32;    // IDEC start latency (PCSX2: 64 EE cycles)
  std::int64_t inFifoQwords = 8;           // input FIFO depth
  std::int64_t inBufferQwords = 2;         // internal bit buffer (IPU_BP.FP)
  std::int64_t outFifoQwords = 8;          // output FIFO depth
  std::int64_t toIpuCyclesPerQword = 1;    // DMAC ch4 (toIPU) rate
  std::int64_t fromIpuCyclesPerQword = 1;  // DMAC ch3 (fromIPU) rate
};

void describeParams(ParamTable& table, IpuTimingParams& p);

}  // namespace vbim::ipu
