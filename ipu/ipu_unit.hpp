// The IPU on the simulated clock, as on the console three channels working at once:
//
//   toIPU   DMAC channel 4: picture bytes from EE memory into the 8-qword input FIFO
//   IDEC    per macroblock, waits for its bits, then base + per-bit cycles (VLC, IQ, IDCT), then
//           CSC row by row, each row's 4 qwords pushed into the 8-qword output FIFO (blocking when
//           it is full: decode stalls when the output is not drained)
//   fromIPU DMAC channel 3: output FIFO to EE memory
//
// The pixels come from the functional decoder (ipu/picture_decoder.hpp), computed on the host when
// the command starts. The qword timing of all three channels is computed on the host too
// (ipu/ipu_unit_timing.hpp); one process, "ipu", sleeps from one observable event to the next (a
// trace span ends, the command completes) instead of stepping every qword. The player (issue #7)
// calls `co_await unit.decode(bytes, image)`.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/ipu_unit_timing.hpp"
#include "ipu/params.hpp"
#include "ipu/picture_decoder.hpp"
#include "runtime/event.hpp"
#include "runtime/fifo.hpp"
#include "runtime/image.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/task.hpp"
#include "runtime/trace.hpp"

namespace vbim::ipu {

struct TimedPicture {
  PictureReport report;
  Tick started = 0;               // command issued
  Tick finished = 0;              // last output qword in memory
  std::int64_t outputStalls = 0;  // CSC rows that waited for room in the output FIFO
  std::int64_t idecCommands = 0;  // IDEC issued: one per slice (the EE restarts it at each slice start code)
  std::int64_t outputQwords = 0;  // written by fromIPU DMA: 64 per macroblock, in macroblock order
};

class IpuUnit {
 public:
  // The inverse DCT is the platform's (p.idct), whatever options.idct says.
  IpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer = nullptr, DecoderOptions options = {});
  IpuUnit(const IpuUnit&) = delete;
  IpuUnit& operator=(const IpuUnit&) = delete;

  // Decodes one picture (see Decoder::decode for what `bytes` holds) to RGB32 with the SETTH
  // thresholds; `out` is written while the fromIPU DMA runs and complete when this returns.
  // One command at a time: callers serialise (as the EE does with IPU_CMD).
  Task<TimedPicture> decode(std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th = {});

  // Fault injection: the DMA channel moves nothing from now for `duration` ticks (a D_CTRL stall,
  // or an EE that does not service the channel). A stalled fromIPU lets the output FIFO fill and
  // the decode stall; a stalled toIPU starves it. A stall still in progress is not extended.
  // Takes effect from the start of the current tick: call it from a process that runs before the
  // IPU's events of that tick (as a fault process scheduled in advance does).
  void stallInputDma(Tick duration);
  void stallOutputDma(Tick duration);
  const Decoder& decoder() const { return decoder_; }
  // Slice-parallel decode on host threads (null: on the calling thread). Same bytes and ticks
  // either way: only the host's wall time changes.
  void setSliceRunner(SliceRunner* runner) { runner_ = runner; }

  // Tests: keep when every qword entered and left each FIFO, one entry per command from now on.
  void recordQwords() { recordQwords_ = true; }
  std::vector<CommandTiming::Qwords> qwordLog() const;

 private:
  // One command: what the timing needs, its schedule, and the output waiting for its time.
  struct Command {
    explicit Command(Scheduler& s) : finishedEvent(s) {}
    CommandTiming timing;
    IpuTimeline::State before;  // the timeline before this command, to plan it again after a stall
    Rgba8Image staged;          // the IPU's output, whole macroblocks
    bool done = false;
    Event finishedEvent;
  };
  using CommandRef = std::shared_ptr<Command>;
  static Task<void> run(IpuUnit& u);
  void retire();
  void replan();

  Scheduler& s_;
  IpuParams p_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Decoder decoder_;
  SliceRunner* runner_ = nullptr;
  IpuTimeline timeline_;
  DmaStalls inStalls_;
  DmaStalls outStalls_;
  std::deque<CommandRef> inFlight_;  // planned commands whose last event is not yet past
  Fifo<CommandRef> commands_;
  bool recordQwords_ = false;
  std::vector<CommandRef> recorded_;
};

}  // namespace vbim::ipu
