// Every timing constant and buffer size of the EE side of playback (the demux thread, the
// compressed and decoded frame buffers), registered under "ee." in the platform config. No
// measured figures exist for a VBIM player on the EE: every default is an assumption, with its
// reasoning in docs/timing/ee.md.
#pragma once

#include <cstdint>

#include "ipu/bdec_flow_timing.hpp"
#include "runtime/param_table.hpp"

namespace vbim::ee {

struct EeParams {
  std::int64_t read_sectors = 16;              // sectors asked per sceCdStRead (STMNBLK)
  std::int64_t poll_us = 1'000;                // retry after a read that returned nothing
  std::int64_t cycles_per_pack = 400;          // EE cycles to parse one pack header + PES headers
  std::int64_t cycles_per_byte = 2;            // EE cycles per payload byte (start-code scan, copy to stream buffer)
  std::int64_t copy_cycles_per_qword = 4;      // EE cycles per 16 bytes copied into the compressed frame buffer
  std::int64_t reorder_cycles_per_qword = 8;   // EE cycles per 16 bytes moved from macroblock to raster order
  std::int64_t compressed_frames = 2;          // compressed frame buffer depth, pictures per stream
  std::int64_t compressed_budget_kib = 4'096;  // EE RAM per stream for pictures, beyond the depth too
  std::int64_t decoded_frames = 2;             // decoded frame buffers per stream in EE RAM
  std::int64_t decode_setup_cycles = 2'000;    // EE cycles to set up one IPU command (DMA tags, IPU_CMD)
  std::int64_t start_lead_ms = 500;            // the stream starts this long before frame 0 is due
  // The EE's share of P and B pictures (the BDEC flow of ps2sdk's libmpeg), EE cycles.
  ipu::EeFlowCosts mc;
};

void describeParams(ParamTable& t, EeParams& p);

}  // namespace vbim::ee
