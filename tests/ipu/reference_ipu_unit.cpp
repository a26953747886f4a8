#include "tests/ipu/reference_ipu_unit.hpp"

#include <algorithm>
#include <cstring>

namespace vbim::ipu::reference {
namespace {

DecoderOptions withTrace(DecoderOptions o) {
  o.recordMacroblocks = true;
  o.freshStorePerDecode = true;  // as IpuUnit: a concealed macroblock is mid-grey
  return o;
}

}  // namespace

ReferenceIpuUnit::ReferenceIpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer, DecoderOptions options)
    : s_(s),
      p_(p),
      tracer_(tracer && tracer->enabled() ? tracer : nullptr),
      decoder_(withTrace(options)),
      toIpuJobs_(s, 1, "ipu.toipu_jobs"),
      coreJobs_(s, 1, "ipu.core_jobs"),
      fromIpuJobs_(s, 1, "ipu.fromipu_jobs"),
      // The internal bit buffer holds qwords taken from the FIFO ahead of the decoder.
      in_(s, static_cast<std::size_t>(p.in_fifo_qwords + p.in_buffer_qwords), "ipu.in"),
      out_(s, static_cast<std::size_t>(p.out_fifo_qwords), "ipu.out") {
  if (tracer_) track_ = tracer_->track("ipu");
  toIpu_ = &s_.spawn("ipu.toIPU", toIpuLoop(*this));
  core_ = &s_.spawn("ipu", coreLoop(*this));
  fromIpu_ = &s_.spawn("ipu.fromIPU", fromIpuLoop(*this));
}

Task<TimedPicture> ReferenceIpuUnit::decode(std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th) {
  TimedPicture result;
  result.started = s_.now();
  const JobRef shared = std::make_shared<Job>(s_);
  Job& job = *shared;
  result.report = decoder_.decode(bytes, nullptr, RgbaOutput{&job.staged, th, true});
  if (!result.report.produced) {
    result.finished = s_.now();
    co_return result;
  }
  const FrameStore& fs = decoder_.frame();
  job.mbWidth = fs.mbWidth;
  const std::size_t mbs = static_cast<std::size_t>(fs.mbWidth) * fs.mbHeight;
  job.inQwords = static_cast<std::uint32_t>((bytes.size() + 15) / 16);
  // Per macroblock (raster order): the qwords holding its last bit, and its bit count. Concealed
  // macroblocks cost the base only and need no further input.
  std::vector<std::uint32_t> endByte(mbs, 0);
  job.bits.assign(mbs, 0);
  for (const MacroblockBits& m : decoder_.macroblockTrace()) {
    if (m.address < mbs) {
      endByte[m.address] = m.endByte;
      job.bits[m.address] = m.bits;
    }
  }
  job.restart = idecRestarts(decoder_.macroblockTrace(), mbs);
  result.idecCommands = 1 + std::count(job.restart.begin(), job.restart.end(), std::uint8_t{1});
  job.needQwords.resize(mbs);
  std::uint32_t need = 0;
  for (std::size_t i = 0; i < mbs; ++i) {
    need = std::max(need, std::min(job.inQwords, (endByte[i] + 15) / 16));
    job.needQwords[i] = need;
  }
  if (out.width != decoder_.width() || out.height != decoder_.height())
    out = Rgba8Image(decoder_.width(), decoder_.height());
  job.out = &out;
  co_await toIpuJobs_.push(shared);
  co_await coreJobs_.push(shared);
  co_await fromIpuJobs_.push(shared);
  while (!job.done) co_await job.finished.wait();
  job.out = nullptr;  // the caller's image: only fromIPU wrote it, and it is done
  result.finished = s_.now();
  result.outputStalls = job.stalls;
  co_return result;
}

Task<void> ReferenceIpuUnit::toIpuLoop(ReferenceIpuUnit& u) {
  for (;;) {
    const JobRef job = co_await u.toIpuJobs_.pop();
    for (std::uint32_t q = 0; q < job->inQwords; ++q) {
      co_await u.s_.delay(u.p_.toipu_cycles_per_qword);
      co_await u.in_.push(q);
      u.sample();
    }
  }
}

Task<void> ReferenceIpuUnit::coreLoop(ReferenceIpuUnit& u) {
  for (;;) {
    const JobRef job = co_await u.coreJobs_.pop();
    co_await u.s_.delay(u.p_.idec_start_cycles);
    std::uint32_t pulled = 0;
    std::uint32_t q = 0;
    const std::size_t mbs = job->needQwords.size();
    const Tick restartCycles = u.p_.slice_restart_cycles + u.p_.idec_start_cycles;
    for (std::size_t i = 0; i < mbs; ++i) {
      // IDEC stopped at the slice start code; the EE reads the slice header and issues it again.
      if (job->restart[i] != 0 && restartCycles > 0) {
        const Tick stopped = u.s_.now();
        co_await u.s_.delay(restartCycles);
        if (u.tracer_) u.tracer_->span(u.track_, stopped, u.s_.now(), "idec restart");
      }
      // The decoder consumes the macroblock's qwords while it works: the cost is spread over them,
      // so the toIPU DMA refills the FIFO during the decode and only a slower DMA makes it wait.
      const Tick begin = u.s_.now();
      const Tick cost = u.p_.mb_base_cycles + u.p_.mb_cycles_per_bit * job->bits[i];
      const std::uint32_t k = job->needQwords[i] - pulled;
      if (k == 0) co_await u.s_.delay(cost);
      for (std::uint32_t j = 1; j <= k; ++j) {
        co_await u.s_.delay(cost * j / k - cost * (j - 1) / k);
        co_await u.in_.pop();
        u.sample();
        ++pulled;
      }
      const Tick decoded = u.s_.now();
      // Per macroblock (a few us) only in full detail; otherwise the same label throughout, so the
      // tracer joins a busy stretch into one span (at 290 macroblocks/s the two spans per macroblock
      // were 150 MB of trace.json per simulated hour).
      const bool fine = u.tracer_ != nullptr && u.tracer_->detail() == TraceDetail::Full;
      if (u.tracer_) u.tracer_->span(u.track_, begin, decoded, fine ? "idec" : "decode");
      // CSC emits the macroblock row by row; each row's qwords wait for room in the output FIFO.
      for (int row = 0; row < 16; ++row) {
        co_await u.s_.delay(u.p_.csc_cycles_per_mb * (row + 1) / 16 - u.p_.csc_cycles_per_mb * row / 16);
        const Tick ready = u.s_.now();
        for (std::uint32_t k = 0; k < u.qwordsPerRow_; ++k) {
          co_await u.out_.push(q++);
          u.sample();
        }
        if (u.s_.now() != ready) {
          ++job->stalls;
          if (fine) u.tracer_->span(u.track_, ready, u.s_.now(), "out stall");
        }
      }
      if (u.tracer_) u.tracer_->span(u.track_, decoded, u.s_.now(), fine ? "csc" : "decode");
    }
    // Bytes after the last macroblock (stuffing, the next start code) are read and dropped.
    while (pulled < job->inQwords) {
      co_await u.in_.pop();
      u.sample();
      ++pulled;
    }
  }
}

Task<void> ReferenceIpuUnit::fromIpuLoop(ReferenceIpuUnit& u) {
  for (;;) {
    const JobRef job = co_await u.fromIpuJobs_.pop();
    const std::uint32_t total = static_cast<std::uint32_t>(job->needQwords.size()) * 16 * u.qwordsPerRow_;
    for (std::uint32_t n = 0; n < total; ++n) {
      const std::uint32_t q = co_await u.out_.pop();
      u.sample();
      co_await u.s_.delay(u.p_.fromipu_cycles_per_qword);
      u.writeQword(*job, q);
    }
    job->done = true;
    job->finished.notify();
  }
}

void ReferenceIpuUnit::sample() {
  if (recording_ == nullptr) return;
  recording_->in.push_back({s_.now(), in_.size()});
  recording_->out.push_back({s_.now(), out_.size()});
}

void ReferenceIpuUnit::writeQword(const Job& job, std::uint32_t q) {
  // RGB32: 16 x 16 x 4 bytes / 16 = 64 qwords a macroblock, 4 pixels each (docs/hardware.md#idec);
  // RGB16: 32, 8 pixels each (the picture's RGB32 pixels are written where that qword's land).
  const std::uint32_t perMacroblock = 16 * qwordsPerRow_;
  const int pixels = 16 / static_cast<int>(qwordsPerRow_);
  const std::uint32_t mb = q / perMacroblock;
  const std::uint32_t within = q % perMacroblock;
  const int px = static_cast<int>(mb % job.mbWidth) * 16 + static_cast<int>(within % qwordsPerRow_) * pixels;
  const int py = static_cast<int>(mb / job.mbWidth) * 16 + static_cast<int>(within / qwordsPerRow_);
  Rgba8Image& out = *job.out;
  if (py >= out.height || px >= out.width) return;
  const int n = std::min(pixels, out.width - px);
  std::memcpy(out.row(py) + 4 * px, job.staged.row(py) + 4 * px, static_cast<std::size_t>(n) * 4);
}

}  // namespace vbim::ipu::reference
