#include "ipu/ipu_unit.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace vbim::ipu {
namespace {

// The timing needs the macroblock trace. One IPU decodes the lightmap's and the sky's pictures in
// turn: a macroblock it conceals is mid-grey, never the picture decoded before (maybe the other
// stream's), and the same whatever came before, as in replay, which decodes each picture alone.
DecoderOptions unitOptions(DecoderOptions o, const IpuParams& p) {
  o.recordMacroblocks = true;
  o.idct = idctKindOf(p);  // the platform's IDCT
  o.freshStorePerDecode = true;
  return o;
}

}  // namespace

IpuUnit::IpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer, DecoderOptions options)
    : s_(s),
      p_(p),
      tracer_(tracer && tracer->enabled() ? tracer : nullptr),
      decoder_(unitOptions(options, p)),
      timeline_(p),
      commands_(s, 1, "ipu.commands") {
  if (tracer_) track_ = tracer_->track("ipu");
  s_.spawn("ipu", run(*this));
}

Task<TimedPicture> IpuUnit::decode(std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th) {
  TimedPicture result;
  result.started = s_.now();
  const CommandRef shared = std::make_shared<Command>(s_);
  Command& cmd = *shared;
  // Decode into out's buffer: when it already has the picture's size (a recycled image), nothing is
  // allocated or cleared; every byte is written either way.
  cmd.staged = std::move(out);
  out = Rgba8Image{};
  result.report = decoder_.decode(bytes, runner_, RgbaOutput{&cmd.staged, th, true});
  if (!result.report.produced) {
    result.finished = s_.now();
    co_return result;
  }
  const FrameStore& fs = decoder_.frame();
  const std::size_t mbs = static_cast<std::size_t>(fs.mbWidth) * fs.mbHeight;
  CommandTiming& tm = cmd.timing;
  tm.arrival = s_.now();
  tm.inQwords = static_cast<std::uint32_t>((bytes.size() + 15) / 16);
  // Per macroblock (raster order): the qwords holding its last bit, and its bit count. Concealed
  // macroblocks cost the base only and need no further input.
  std::vector<std::uint32_t> endByte(mbs, 0);
  tm.bits.assign(mbs, 0);
  for (const MacroblockBits& m : decoder_.macroblockTrace()) {
    if (m.address < mbs) {
      endByte[m.address] = m.endByte;
      tm.bits[m.address] = m.bits;
    }
  }
  tm.restart = idecRestarts(decoder_.macroblockTrace(), mbs);
  result.idecCommands = 1 + std::count(tm.restart.begin(), tm.restart.end(), std::uint8_t{1});
  result.outputQwords = static_cast<std::int64_t>(mbs) * kQwordsPerMacroblock;
  tm.needQwords.resize(mbs);
  std::uint32_t need = 0;
  for (std::size_t i = 0; i < mbs; ++i) {
    need = std::max(need, std::min(tm.inQwords, (endByte[i] + 15) / 16));
    tm.needQwords[i] = need;
  }
  retire();
  cmd.before = timeline_.state();
  timeline_.plan(tm, inStalls_, outStalls_, recordQwords_);
  inFlight_.push_back(shared);
  if (recordQwords_) recorded_.push_back(shared);
  co_await commands_.push(shared);
  while (!cmd.done) co_await cmd.finishedEvent.wait();
  // The picture is in memory: the caller sees it whole (no one reads it while the DMA runs).
  if (cmd.staged.width == decoder_.width() && cmd.staged.height == decoder_.height()) {
    out = std::move(cmd.staged);  // whole macroblocks are the picture: hand the buffer over
  } else {
    if (out.width != decoder_.width() || out.height != decoder_.height())
      out = Rgba8Image(decoder_.width(), decoder_.height());
    for (int y = 0; y < out.height; ++y)
      std::memcpy(out.row(y), cmd.staged.row(y), static_cast<std::size_t>(out.width) * 4);
  }
  result.finished = s_.now();
  result.outputStalls = tm.stalls;
  co_return result;
}

// Sleeps from one observable event of the command to the next: the end of each trace span (as the
// qword-stepping model recorded them, at the tick they ended) and the last qword's write. Each time
// is read again on waking: a DMA stall may have moved it later.
Task<void> IpuUnit::run(IpuUnit& u) {
  Scheduler& s = u.s_;
  for (;;) {
    const CommandRef ref = co_await u.commands_.pop();
    const CommandTiming& tm = ref->timing;
    if (u.tracer_) {
      // Per macroblock (a few us) only in full detail; otherwise the same label throughout, so the
      // tracer joins a busy stretch into one span (at 290 macroblocks/s the two spans per macroblock
      // were 150 MB of trace.json per simulated hour).
      const bool fine = u.tracer_->detail() == TraceDetail::Full;
      std::size_t stall = 0;
      const Tick restartCycles = u.p_.slice_restart_cycles + u.p_.idec_start_cycles;
      for (std::size_t i = 0; i < tm.mbEnd.size(); ++i) {
        // The EE's restart of IDEC at a slice start code: the IPU core idles.
        if (tm.restart[i] != 0 && restartCycles > 0) {
          while (s.now() < tm.mbBegin[i]) co_await s.until(tm.mbBegin[i]);
          u.tracer_->span(u.track_, tm.mbBegin[i] - restartCycles, tm.mbBegin[i], "idec restart");
        }
        while (s.now() < tm.mbDecoded[i]) co_await s.until(tm.mbDecoded[i]);
        u.tracer_->span(u.track_, tm.mbBegin[i], tm.mbDecoded[i], fine ? "idec" : "decode");
        // CSC rows that waited for room (full detail), then the macroblock's end. A stall that
        // starts while this sleeps can add a row stall ending before the tick it wakes at: that
        // span is recorded then, in order, with its own times.
        for (;;) {
          if (fine && stall < tm.rowStalls.size() && tm.rowStalls[stall].mb == i) {
            if (s.now() < tm.rowStalls[stall].end) {
              co_await s.until(tm.rowStalls[stall].end);
              continue;
            }
            u.tracer_->span(u.track_, tm.rowStalls[stall].ready, tm.rowStalls[stall].end, "out stall");
            ++stall;
            continue;
          }
          if (s.now() >= tm.mbEnd[i]) break;
          co_await s.until(tm.mbEnd[i]);
        }
        u.tracer_->span(u.track_, tm.mbDecoded[i], tm.mbEnd[i], fine ? "csc" : "decode");
      }
    }
    // The last qword's DMA period starts where the stepping model started it, so the caller
    // resumes in the same order among the events of that tick.
    while (s.now() < tm.lastResume) co_await s.until(tm.lastResume);
    while (s.now() < tm.finished) co_await s.until(tm.finished);
    ref->done = true;
    ref->finishedEvent.notify();
  }
}

void IpuUnit::retire() {
  while (!inFlight_.empty() && inFlight_.front()->timing.quietAfter < s_.now()) inFlight_.pop_front();
}

// A stall moves nothing before now: plan again from the oldest command with an event still ahead.
void IpuUnit::replan() {
  retire();
  if (inFlight_.empty()) return;
  timeline_.restore(inFlight_.front()->before);
  for (const CommandRef& c : inFlight_) {
    c->before = timeline_.state();
    timeline_.plan(c->timing, inStalls_, outStalls_, recordQwords_);
  }
}

void IpuUnit::stallInputDma(Tick duration) {
  if (inStalls_.add(s_.now(), duration)) replan();
}

void IpuUnit::stallOutputDma(Tick duration) {
  if (outStalls_.add(s_.now(), duration)) replan();
}

std::vector<CommandTiming::Qwords> IpuUnit::qwordLog() const {
  std::vector<CommandTiming::Qwords> log;
  for (const CommandRef& c : recorded_) log.push_back(c->timing.qwords);
  return log;
}

}  // namespace vbim::ipu
