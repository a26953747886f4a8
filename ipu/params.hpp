// Every timing constant of the IPU model, registered under the prefix "ipu." in the platform
// config. Defaults and their reasoning: docs/timing/ipu.md and
// docs/hardware.md#ipu-decode-cost.
#pragma once

#include <cstdint>
#include <string>

#include "ipu/kernels.hpp"
#include "runtime/param_table.hpp"

namespace vbim::ipu {

struct IpuParams {
  std::int64_t mb_base_cycles = 400;              // per macroblock, VLD + IQ + IDCT fixed part
  std::int64_t mb_cycles_per_bit = 1;             // per input bit of the macroblock
  std::int64_t csc_cycles_per_mb = 256;           // colour conversion, 1 pixel per cycle
  std::int64_t idec_start_cycles = 32;            // IDEC start latency (PCSX2: 64 EE cycles)
  std::int64_t slice_restart_cycles = 300;        // EE restart of IDEC at each later slice (assumption)
  std::int64_t in_fifo_qwords = 8;                // input FIFO depth
  std::int64_t in_buffer_qwords = 2;              // internal bit buffer (IPU_BP.FP)
  std::int64_t out_fifo_qwords = 8;               // output FIFO depth
  std::int64_t toipu_cycles_per_qword = 1;        // DMAC ch4 (toIPU) rate
  std::int64_t fromipu_cycles_per_qword = 1;      // DMAC ch3 (fromIPU) rate
  std::string idct = idctKindName(kDefaultIdct);  // the inverse DCT: "pcsx2", "libmpeg2" or "exact"
  // The commands of the BDEC flow (P and B pictures, ipu/bdec_flow_timing.hpp); BDEC itself costs
  // idec_start_cycles + mb_base_cycles + mb_cycles_per_bit x its bits, like IDEC without CSC.
  std::int64_t vdec_cycles = 8;    // one variable-length symbol (assumption)
  std::int64_t fdec_cycles = 4;    // a fixed-length read (assumption)
  std::int64_t setiq_cycles = 64;  // a 64-byte quantiser matrix from the FIFO (assumption)
  std::int64_t setvq_cycles = 32;  // a 16-colour CLUT, 32 bytes (assumption; not issued by an RGB32 player)
  std::int64_t bclr_cycles = 0;    // PCSX2: immediate
};

// The IdctKind named by p.idct (a choice parameter, so always one of the three).
IdctKind idctKindOf(const IpuParams& p);

void describeParams(ParamTable& table, IpuParams& p);

}  // namespace vbim::ipu
