// The IPU's timing as a recurrence over qwords, computed on the host instead of stepped on the
// scheduler (issue #17). It gives, tick for tick, what three cooperating threads moving every
// qword through the FIFOs would give (the model it replaced, kept in tests/ipu/reference_ipu_unit.*):
//
//   toIPU  (DMAC ch4)  qword x enters the input FIFO at   P(x) = max(A(x), Pop(x - Din))
//                      where A(x) is one DMA period after the channel was free again
//   IDEC + CSC         pops qword x at                    Pop(x) = max(request, P(x))
//                      pushes output qword y at           Q(y) = max(request, Take(y - Dout))
//   fromIPU (DMAC ch3) takes output qword y at            Take(y) = max(R(y), Q(y))
//                      and writes it one DMA period after it resumed
//
// Each term only looks back at earlier qwords, so a command's whole schedule follows in one pass.
// A DMA stall (a channel suspended from outside: D_CTRL, or an EE that does not service the
// interrupt) holds every wake-up of that channel that falls inside it until it ends, as
// Scheduler::suspendFor does to a process; a FIFO hand-over to a waiting channel still happens.
// A stall moves no event earlier, and none before it, so a schedule is recomputed from the oldest
// command still in flight when one starts.
#pragma once

#include <cstdint>
#include <vector>

#include "ipu/params.hpp"
#include "ipu/slice_decoder.hpp"
#include "runtime/clock.hpp"

namespace vbim::ipu {

// The IPU's RGB32 output of one macroblock: 16 rows of 4 quadwords (16 pixels x 4 bytes),
// 64 quadwords in all; RGB16 (IDEC or CSC with OFM = 1) is 2 quadwords a row, 32 in all
// (docs/hardware.md#idec).
inline constexpr int kRowsPerMacroblock = 16;
inline constexpr int kQwordsPerRow = 4;
inline constexpr int kQwordsPerRow16 = 2;
inline constexpr int kQwordsPerMacroblock = kRowsPerMacroblock * kQwordsPerRow;
inline constexpr int kQwordsPerMacroblock16 = kRowsPerMacroblock * kQwordsPerRow16;

// The stalls of one DMA channel: each holds [from, to] (a wake-up at `to` itself is on time).
class DmaStalls {
 public:
  // A stall from `now` for `duration`; a stall still in progress is not extended (as
  // Scheduler::suspend on a suspended process). Returns whether a stall was added.
  bool add(Tick now, Tick duration);
  // No stall holds any time in [from, to].
  bool clear(Tick from, Tick to) const { return windows_.empty() || clearSlow(from, to); }
  // No stall holds any time from `from` on (so defer(t) == t for every t >= from).
  bool clearFrom(Tick from) const { return windows_.empty() || windows_.back().to < from; }
  // The time a wake-up due at t happens.
  Tick defer(Tick t) const {
    if (windows_.empty() || t < windows_.front().from) return t;
    return deferSlow(t);
  }

 private:
  struct Window {
    Tick from;
    Tick to;
  };
  Tick deferSlow(Tick t) const;
  bool clearSlow(Tick from, Tick to) const;
  std::vector<Window> windows_;  // in time order, disjoint
};

// One command (IDEC of one picture) as the timing sees it, and its schedule.
struct CommandTiming {
  // In.
  Tick arrival = 0;                       // decode() issued it
  std::uint32_t inQwords = 0;             // bytes moved by toIPU, in qwords
  std::vector<std::uint32_t> needQwords;  // per macroblock: input qwords needed before it starts
  std::vector<std::uint32_t> bits;        // per macroblock: its bits (cost)
  // Per macroblock: 1 when IDEC stopped at a slice start code before it and the EE issued it again
  // (slice_restart_cycles + idec_start_cycles before it begins). The command's first IDEC is not one.
  std::vector<std::uint8_t> restart;
  // CSC of YCbCr macroblocks from EE memory (the BDEC flow's display frame, 24 input qwords per
  // macroblock in needQwords): no start delay and no decode cost, only csc_cycles_per_mb.
  bool csc = false;
  // Output qwords per macroblock row: kQwordsPerRow (RGB32) or kQwordsPerRow16 (RGB16, OFM = 1).
  int qwordsPerRow = kQwordsPerRow;

  // Out, per macroblock: started, last input qword popped, last output qword pushed.
  std::vector<Tick> mbBegin;
  std::vector<Tick> mbDecoded;
  std::vector<Tick> mbEnd;
  struct RowStall {
    std::uint32_t mb;
    Tick ready;  // the CSC row was ready
    Tick end;    // its last qword was in the output FIFO
  };
  std::vector<RowStall> rowStalls;  // in output order
  std::int64_t stalls = 0;
  Tick lastResume = 0;  // fromIPU resumed with the last output qword (its final DMA period follows)
  Tick finished = 0;    // the last output qword is in memory
  Tick quietAfter = 0;  // the last event of the command (input after the last macroblock included)

  // Per qword, only when recording (tests): entered and left the input and output FIFOs.
  struct Qwords {
    std::vector<Tick> inEnter, inLeave, outEnter, outLeave;
  } qwords;
};

// Per macroblock of a picture of `mbs` macroblocks: 1 where the EE re-issues IDEC, at the first
// macroblock of every slice but the first one decoded (IDEC stops at each slice start code).
std::vector<std::uint8_t> idecRestarts(const std::vector<MacroblockBits>& trace, std::size_t mbs);

// Where the three channels are between commands, and the recent FIFO history the next one needs.
class IpuTimeline {
 public:
  explicit IpuTimeline(const IpuParams& p);

  // Computes `c` following every command planned before it.
  void plan(CommandTiming& c, const DmaStalls& in, const DmaStalls& out, bool recordQwords);

  struct State {
    Tick toIpuFree = 0;    // toIPU resumed after its last push
    Tick coreFree = 0;     // the core dropped its last input qword
    Tick fromIpuFree = 0;  // fromIPU wrote its last qword
    std::uint64_t inCount = 0;
    std::uint64_t outCount = 0;
    std::vector<Tick> inPops;    // Pop of the last Din input qwords, by index mod Din
    std::vector<Tick> outTakes;  // Take of the last Dout + 1 output qwords, by index mod (Dout + 1)
  };
  const State& state() const { return st_; }
  // Nothing of the channels before `t`: a BDEC flow (ipu/bdec_flow_timing.hpp) used them until then
  // and left both FIFOs empty.
  void advanceTo(Tick t);
  void restore(const State& s) { st_ = s; }

 private:
  IpuParams p_;
  std::uint64_t din_;
  std::uint64_t dout_;
  State st_;
  std::vector<Tick> outPushes_;  // Q of output qwords not yet taken, by index mod (Dout + 1)
  // A CSC command's steady state (plan): the channels and FIFOs after one macroblock and after the
  // one before it, relative to each one's end.
  std::vector<Tick> steadyNow_;
  std::vector<Tick> steadyBefore_;
};

}  // namespace vbim::ipu
