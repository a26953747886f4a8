// The qword-stepping IPU timing model that ipu/ipu_unit.hpp replaced (issue #17), kept verbatim as
// the reference of tests/ipu/ipu_unit_equivalence_test.cpp. Additions: record(), the level of both
// FIFOs after every push and pop, to compare against the stepped model; and the EE's restart of
// IDEC at each slice after the first (the core waits slice_restart_cycles + idec_start_cycles); and
// RGB16 output (setRgb16Output: 2 qwords a row instead of 4, each qword 8 pixels of the picture).
//
// The IPU on the simulated clock: three cooperating threads, as on the console.
//
//   "ipu.toIPU"   DMAC channel 4: picture bytes from EE memory into the 8-qword input FIFO
//   "ipu"         IDEC: per macroblock, waits for its bits, then base + per-bit cycles (VLC, IQ,
//                 IDCT), then CSC row by row, each row's 4 qwords pushed into the 8-qword output
//                 FIFO (blocking when it is full: decode stalls when the output is not drained)
//   "ipu.fromIPU" DMAC channel 3: output FIFO to EE memory, writing the pixels of each qword into
//                 the caller's image when that qword lands
//
// The pixels come from the functional decoder (ipu/picture_decoder.hpp), computed on the host when
// the command starts and released qword by qword at the modelled times. The player (issue #7)
// calls `co_await unit.decode(bytes, image)`.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/ipu_unit.hpp"
#include "ipu/params.hpp"
#include "ipu/picture_decoder.hpp"
#include "runtime/event.hpp"
#include "runtime/fifo.hpp"
#include "runtime/image.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/task.hpp"
#include "runtime/trace.hpp"

namespace vbim::ipu::reference {

// FIFO levels as the model leaves them after an operation (several per tick).
struct FifoSample {
  Tick t = 0;
  std::size_t level = 0;
};
struct FifoRecording {
  std::vector<FifoSample> in;
  std::vector<FifoSample> out;
};

class ReferenceIpuUnit {
 public:
  ReferenceIpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer = nullptr, DecoderOptions options = {});
  ReferenceIpuUnit(const ReferenceIpuUnit&) = delete;
  ReferenceIpuUnit& operator=(const ReferenceIpuUnit&) = delete;

  // Decodes one picture (see Decoder::decode for what `bytes` holds) to RGB32 with the SETTH
  // thresholds; `out` is written while the fromIPU DMA runs and complete when this returns.
  // One command at a time: callers serialise (as the EE does with IPU_CMD).
  Task<TimedPicture> decode(std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th = {});

  // For fault injection: suspending this process stops the output drain (D_CTRL stall, or an EE
  // that does not service the DMA), so the output FIFO fills and the decode stalls.
  Process& fromIpuProcess() { return *fromIpu_; }
  Process& toIpuProcess() { return *toIpu_; }
  Process& coreProcess() { return *core_; }
  const Decoder& decoder() const { return decoder_; }
  void record(FifoRecording* r) { recording_ = r; }
  void setRgb16Output() { qwordsPerRow_ = 2; }

 private:
  // One command's data. The three loops share it: decode() returns when the output is in memory,
  // but toIPU may still be moving, and the core dropping, input after the last macroblock (stuffing,
  // or the rest of a picture whose last macroblocks were concealed), so each loop holds the job
  // until it is done with it.
  struct Job {
    explicit Job(Scheduler& s) : finished(s) {}
    std::uint32_t inQwords = 0;
    // Per macroblock in output order: input qwords needed before it can start, and its bits.
    std::vector<std::uint32_t> needQwords;
    std::vector<std::uint32_t> bits;
    std::vector<std::uint8_t> restart;  // IDEC re-issued by the EE before this macroblock (a new slice)
    int mbWidth = 0;
    Rgba8Image staged;  // the IPU's output, whole macroblocks
    Rgba8Image* out = nullptr;
    std::int64_t stalls = 0;
    bool done = false;
    Event finished;
  };
  using JobRef = std::shared_ptr<Job>;
  static Task<void> toIpuLoop(ReferenceIpuUnit& u);
  static Task<void> coreLoop(ReferenceIpuUnit& u);
  static Task<void> fromIpuLoop(ReferenceIpuUnit& u);
  void writeQword(const Job& job, std::uint32_t q);
  void sample();

  Scheduler& s_;
  IpuParams p_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Decoder decoder_;
  Fifo<JobRef> toIpuJobs_;
  Fifo<JobRef> coreJobs_;
  Fifo<JobRef> fromIpuJobs_;
  Fifo<std::uint32_t> in_;
  Fifo<std::uint32_t> out_;
  Process* toIpu_ = nullptr;
  Process* core_ = nullptr;
  Process* fromIpu_ = nullptr;
  FifoRecording* recording_ = nullptr;
  std::uint32_t qwordsPerRow_ = 4;  // RGB32; 2 for RGB16
};

}  // namespace vbim::ipu::reference
