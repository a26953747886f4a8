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
//
// Streams (issue #29): each stream the caller opens has its own functional decoder, so the
// lightmap's and the sky's reference frames never mix. A stream is decoded one of two ways, as a
// console player would choose:
//   DecodePath::kIdec  intra pictures by IDEC (+CSC); a P or B picture is refused (IDEC decodes
//                      intra macroblocks only, and its RGB output leaves no YCbCr reference).
//   DecodePath::kBdec  every picture by the flow of ps2sdk's libmpeg: VDEC/FDEC/BDEC per
//                      macroblock, the EE's prediction and residual add, CSC of the frame due for
//                      display (ipu/bdec_flow.hpp, ipu/bdec_flow_timing.hpp). The EE's time is a
//                      track "ee" of the tracer.
// Stream 0 (kSharedIdecStream) is the IDEC stream decode(bytes, image) uses.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "ipu/bdec_flow.hpp"
#include "ipu/bdec_flow_timing.hpp"
#include "ipu/csc.hpp"
#include "ipu/ipu_commands.hpp"
#include "ipu/ipu_unit_shared_decodes.hpp"
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
  std::int64_t outputQwords = 0;  // written by fromIPU DMA: 64 per macroblock (32 in RGB16), in macroblock order
  // `out` holds a new frame: every produced picture on the IDEC path; on the BDEC path when a frame
  // became due for display (display order: an I or P frame when the next one is decoded).
  bool displayed = false;
  IpuCommandCounts commands;  // IDEC path: idec only
  Tick decodeEnd = 0;         // BDEC path: the last macroblock stored (the CSC follows)
  Tick eeBusy = 0;            // BDEC path: the EE's work (parse, command issue, MC, CSC set-up)
  Tick eeWait = 0;            // BDEC path: the EE waiting for BDEC
  // With IpuUnit::recordCommands: IPU_CTRL as set for the picture, and every command issued for it
  // in issue order with its word and time (docs/run-files.md, "ipu_commands.csv").
  std::uint32_t ctrl = 0;
  std::vector<IssuedCommand> issued;
};

enum class DecodePath : std::uint8_t { kIdec, kBdec };
using StreamId = std::size_t;
inline constexpr StreamId kSharedIdecStream = 0;

class IpuUnit {
 public:
  // The inverse DCT is the platform's (p.idct), whatever options.idct says.
  // `ee`: the EE's costs in the BDEC flow (ee.* parameters).
  IpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer = nullptr, DecoderOptions options = {}, EeFlowCosts ee = {});
  IpuUnit(const IpuUnit&) = delete;
  IpuUnit& operator=(const IpuUnit&) = delete;

  // Decodes one picture (see Decoder::decode for what `bytes` holds) to RGB32 with the SETTH
  // thresholds; `out` is written while the fromIPU DMA runs and complete when this returns.
  // One command at a time: callers serialise (as the EE does with IPU_CMD).
  Task<TimedPicture> decode(std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th = {}) {
    return decode(kSharedIdecStream, bytes, out, th);
  }
  // A stream of its own (before the tracer streams its output: a kBdec stream adds the track "ee").
  StreamId openStream(DecodePath path);
  // The picture(s) in `bytes` of `stream`, in stream order. On a kBdec stream `out` is written only
  // when a frame became due for display (TimedPicture::displayed).
  Task<TimedPicture> decode(StreamId stream, std::span<const std::uint8_t> bytes, Rgba8Image& out,
                            CscThresholds th = {});
  // The same into a shared image: with shared decodes (shareDecodes) `out` may come back as the
  // twin IPU's image of the same picture, which no one writes again (a decoded frame is only read).
  Task<TimedPicture> decode(StreamId stream, std::span<const std::uint8_t> bytes, std::shared_ptr<Rgba8Image>& out,
                            CscThresholds th = {});
  // End of a kBdec stream: the last frame not yet displayed, through CSC into `out` (displayed).
  Task<TimedPicture> flush(StreamId stream, Rgba8Image& out, CscThresholds th = {});

  // Fault injection: the DMA channel moves nothing from now for `duration` ticks (a D_CTRL stall,
  // or an EE that does not service the channel). A stalled fromIPU lets the output FIFO fill and
  // the decode stall; a stalled toIPU starves it. A stall still in progress is not extended.
  // Takes effect from the start of the current tick: call it from a process that runs before the
  // IPU's events of that tick (as a fault process scheduled in advance does).
  void stallInputDma(Tick duration);
  void stallOutputDma(Tick duration);
  DecodePath decodePath(StreamId stream) const { return streams_.at(stream).path; }
  StreamId streamCount() const { return streams_.size(); }  // the streams are 0 .. streamCount() - 1
  const Decoder& decoder(StreamId stream = kSharedIdecStream) const { return *streams_.at(stream).decoder; }
  // Slice-parallel decode on host threads (null: on the calling thread). Same bytes and ticks
  // either way: only the host's wall time changes.
  void setSliceRunner(SliceRunner* runner) { runner_ = runner; }

  // The IPU writes RGB16 (IDEC and CSC with OFM = 1, DTE = `dither`): 32 output qwords per macroblock
  // instead of 64, so the fromIPU DMA and the output FIFO carry half (gs.texture_format = ct16).
  // `out` stays RGB32: the pixels the RGB16 output is converted from (gs/blend16.hpp). Call before
  // the first decode.
  void setRgb16Output(bool dither) {
    rgb16_ = true;
    dither_ = dither;
  }
  bool rgb16Output() const { return rgb16_; }
  // Shares the decodes of its IDEC stream with another IPU given the same pictures, as side 0 or 1
  // of `shared` (ipu/ipu_unit_shared_decodes.hpp): same bytes, ticks and reports either way; only
  // the host's work changes. decoder() may then be behind (the decodes it took were not its own).
  void shareDecodes(SharedDecodes& shared, int side);
  // The same for a kBdec stream, with its own `shared` (made with DecoderState::Kept; both IPUs'
  // streams of the same pictures): the twin may take this IPU's decoder state to catch up.
  void shareFlowDecodes(StreamId stream, SharedDecodes& shared, int side);
  // Fill TimedPicture::ctrl and ::issued from now on (the command log of `vbim play --trace-detail
  // ipu`). The BDEC flow's log reads this IPU's own decoder after each picture, so its kBdec streams
  // stop sharing their decodes (SharedDecodes::leave).
  void recordCommands();

  // Tests: keep when every qword entered and left each FIFO, one entry per command from now on.
  void recordQwords() { recordQwords_ = true; }
  std::vector<CommandTiming::Qwords> qwordLog() const;

 private:
  // One command: what the timing needs, its schedule, and the output waiting for its time.
  struct Command {
    explicit Command(Scheduler& s) : finishedEvent(s) {}
    Tick arrival = 0;
    CommandTiming timing;  // IDEC, or the BDEC flow's CSC (timing.csc)
    bool flow = false;     // a BDEC flow picture (then `timing` only if hasCsc)
    bool hasCsc = false;
    FlowPicture flowWork;
    FlowTiming flowTiming;
    IpuTimeline::State before;  // the timeline before this command, to plan it again after a stall
    // The command log (recordCommands): IDEC path, each IDEC (or FDEC skipping a long slice header)
    // with the macroblock its slice starts at, -1 for BCLR and SETTH issued at the start.
    struct PlannedWord {
      std::uint32_t word;
      std::int64_t mb;
    };
    std::vector<PlannedWord> planned;
    Rgba8Image staged;     // the IPU's output, whole macroblocks
    bool inPlace = false;  // with shared decodes: the output is the caller's shared image, not `staged`
    bool done = false;
    Event finishedEvent;
  };
  using CommandRef = std::shared_ptr<Command>;
  struct Stream {
    DecodePath path;
    std::unique_ptr<Decoder> decoder;
    SharedDecodes* flowShare = nullptr;  // kBdec with shareFlowDecodes
    int flowSide = 0;
  };
  static Task<void> run(IpuUnit& u);
  Task<TimedPicture> decodeUnshared(StreamId stream, std::span<const std::uint8_t> bytes, Rgba8Image& out,
                                    CscThresholds th);
  Task<TimedPicture> decodeFlowShared(StreamId stream, std::span<const std::uint8_t> bytes,
                                      std::shared_ptr<Rgba8Image>& out, CscThresholds th);
  Task<TimedPicture> submitIdec(std::shared_ptr<Command> shared, TimedPicture result,
                                std::span<const std::uint8_t> bytes, const IdecDecode& d, CscThresholds th,
                                Rgba8Image& out);
  Task<void> traceCommand(const Command& cmd, bool cscOnly);
  Task<void> traceFlowCoalesced(const Command& cmd);
  Task<TimedPicture> submit(std::shared_ptr<Command> shared, TimedPicture result, Rgba8Image& out, int width,
                            int height);
  void plan(Command& c);
  // The display CSC of a BDEC flow: `shown` converted into cmd.staged (taking `out`'s buffer) and
  // its timing (24 qwords in per macroblock from EE memory); returns the output qwords.
  std::int64_t stageDisplayCsc(Command& cmd, const Decoder& dec, const FrameStore& shown, CscThresholds th,
                               Rgba8Image& out) const;
  // The BDEC flow's work for a decoded picture (bdec_flow.hpp), from its headers and macroblock trace.
  static void stageFlow(Command& cmd, std::span<const std::uint8_t> bytes, const SequenceHeader& seq,
                        const PictureHeader& pic, const std::vector<MacroblockBits>& trace);
  // Its timing alone, for a frame of mbWidth x mbHeight macroblocks; returns the output qwords.
  std::int64_t stageCscTiming(Command& cmd, int mbWidth, int mbHeight) const;
  // The command log of a finished command (recordCommands).
  void planIdecWords(Command& cmd, std::span<const std::uint8_t> bytes, const IdecDecode& d, CscThresholds th) const;
  void planFlowWords(Command& cmd, std::span<const std::uint8_t> bytes, const Decoder& dec) const;
  void logCommands(const Command& cmd, TimedPicture& result) const;
  int qwordsPerRow() const { return rgb16_ ? kQwordsPerRow16 : kQwordsPerRow; }
  static Tick quietAfter(const Command& c);
  void retire();
  void replan();

  Scheduler& s_;
  IpuParams p_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Tracer::TrackId eeTrack_ = 0;
  bool eeTrackOpen_ = false;
  DecoderOptions options_;
  EeFlowCosts ee_;
  std::vector<Stream> streams_;
  SliceRunner* runner_ = nullptr;
  IpuTimeline timeline_;
  DmaStalls inStalls_;
  DmaStalls outStalls_;
  std::deque<CommandRef> inFlight_;  // planned commands whose last event is not yet past
  Fifo<CommandRef> commands_;
  bool recordQwords_ = false;
  std::vector<CommandRef> recorded_;
  bool rgb16_ = false;
  bool dither_ = false;
  bool recordCommands_ = false;
  SharedDecodes* share_ = nullptr;
  int shareSide_ = 0;
};

}  // namespace vbim::ipu
