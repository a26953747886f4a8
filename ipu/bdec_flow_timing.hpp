// The BDEC flow of one picture (ipu/bdec_flow.hpp) on the simulated clock, computed on the host as
// ipu/ipu_unit_timing.hpp computes IDEC: the EE (one thread) and the IPU (one command at a time)
// as libmpeg pipelines them (ps2sdk ee/mpeg/src/libmpeg.c, _mpeg12_slice):
//
//   EE   | parse n (VDEC/FDEC) | issue BDEC n | MC n-1 | wait BDEC n | parse n+1 | issue BDEC n+1 | MC n | ...
//   IPU  |   answers VDEC/FDEC |   BDEC n: VLC, IQ, IDCT -> 48 qwords -> fromIPU -> scratchpad  |   BDEC n+1 ...
//
// The EE predicts macroblock n-1 (and adds its residual) while the IPU decodes n; before parsing
// n+1 it waits for BDEC n to be in memory (_MPEG_WaitBDEC). A skipped macroblock is a pass of the
// loop without IPU commands. The picture's bytes come in by toIPU DMA through the input FIFO
// (in_fifo_qwords + in_buffer_qwords) as the commands read them; BDEC's output leaves through the
// output FIFO by fromIPU DMA, so a stalled fromIPU holds BDEC and the EE with it. The CSC of the
// frame due for display follows as a command of its own (IpuTimeline, CommandTiming::csc).
#pragma once

#include <cstdint>
#include <vector>

#include "ipu/bdec_flow.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/ipu_unit_timing.hpp"
#include "ipu/params.hpp"
#include "runtime/clock.hpp"

namespace vbim::ipu {

// The EE's costs in the flow, EE cycles (the ee.* parameters of ee/params.hpp; defaults and
// reasoning in docs/timing/ee.md).
struct EeFlowCosts {
  std::int64_t vdec_cycles = 240;               // issue VDEC, wait for it, read IPU_CMD and IPU_TOP
  std::int64_t fdec_cycles = 120;               // one GetBits: FDEC and its sync
  std::int64_t bdec_issue_cycles = 300;         // fromIPU DMA to scratchpad and BDEC
  std::int64_t mb_cycles = 400;                 // per macroblock: bookkeeping, reference fetch set-up
  std::int64_t mc_cycles_per_mb = 400;          // store the macroblock's 384 samples into the frame
  std::int64_t mc_cycles_per_prediction = 500;  // one block prediction (half-sample interpolation included)
  std::int64_t mc_average_cycles = 200;         // averaging a second prediction into the first
  std::int64_t residual_add_cycles = 300;       // the residual added to the prediction, with the clip
  std::int64_t csc_setup_cycles = 600;          // _MPEG_CSCImage: suspend, BCLR, DMA and CSC set-up, resume
};

// The EE's MC work for one pass of the loop, in bus cycles.
Tick mcCost(const FlowMacroblock& m, const EeFlowCosts& ee);

struct FlowSpan {
  Tick begin;
  Tick end;
  std::uint8_t track;  // 0 the EE, 1 the IPU
  const char* label;   // "parse", "mc", "bdec"
};

struct FlowTiming {
  Tick arrival = 0;             // the EE starts the picture (after the previous command)
  bool recordCommands = false;  // fill `commands`
  // Step every BDEC output qword through the output FIFO, also where fromIPU keeps up and the
  // result is known without it (the reference the shortcut is tested against).
  bool stepEveryQword = false;
  // Out.
  Tick decodeEnd = 0;             // the last macroblock is predicted and stored
  Tick inFree = 0;                // toIPU after its last qword
  Tick ipuFree = 0;               // the IPU core after its last command
  Tick fromFree = 0;              // fromIPU after its last qword
  Tick eeBusy = 0;                // EE work (parse, command issue, MC); waits for BDEC excluded
  Tick eeWait = 0;                // EE waiting for BDEC (polling, _MPEG_WaitBDEC)
  Tick ipuBusy = 0;               // IPU time in BDEC (decode and output)
  std::int64_t outputStalls = 0;  // BDEC output qwords that waited for room in the output FIFO
  IpuCommandCounts counts;        // BCLR at the picture start, the headers', VDEC, FDEC, BDEC
  std::vector<FlowSpan> spans;    // ordered by end (then begin)
  // With recordCommands, every command in issue order with its time: the picture's BCLR, the
  // headers' (FlowPicture::headerWords), then per macroblock the slice header's 4 FDECs, VDEC of the
  // address increment and the macroblock type, the macroblock's other FDECs, its other VDECs (TBL =
  // motion code), and BDEC (FlowMacroblock::bdecWord). The flow counts a macroblock's reads, not
  // their order or widths: FB is 0 and the reads after the first two VDECs are in that fixed order.
  // A read ends when the EE has its answer; BDEC when its 48 qwords are in memory.
  std::vector<IssuedCommand> commands;
};

// Plans `f` from `t.arrival` with the FIFOs empty (the EE clears them with BCLR when it starts a
// picture: the player's two streams share the IPU).
void planFlow(const FlowPicture& f, const IpuParams& p, const EeFlowCosts& ee, const DmaStalls& in,
              const DmaStalls& out, FlowTiming& t);

}  // namespace vbim::ipu
