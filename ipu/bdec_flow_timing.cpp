#include "ipu/bdec_flow_timing.hpp"

#include <algorithm>

namespace vbim::ipu {
namespace {

// BDEC's output: 384 signed 16-bit samples (Y 16x16, Cb 8x8, Cr 8x8) = 48 qwords (T-IPU BDEC).
constexpr int kBdecQwords = 48;

// The toIPU DMA feeding one picture's bytes through the input FIFO (the recurrence of
// ipu/ipu_unit_timing.hpp): qword x goes in one DMA period after the previous one once qword x - D
// has been read, and is read when a command asks for it and it is there.
class InputFeed {
 public:
  InputFeed(const IpuParams& p, const DmaStalls& stalls, Tick start)
      : stalls_(stalls),
        period_(p.toipu_cycles_per_qword),
        depth_(static_cast<std::size_t>(p.in_fifo_qwords + p.in_buffer_qwords)),
        pops_(depth_, start),
        free_(stalls.defer(start)) {}

  // Reads qwords up to `count` (those not read yet) from `request` on; returns when the last is read.
  Tick readThrough(std::uint32_t count, Tick request) {
    Tick t = request;
    while (read_ < count) {
      const Tick arrive = stalls_.defer(free_ + period_);
      Tick& slot = pops_[slot_];
      if (++slot_ == depth_) slot_ = 0;  // read_ % depth_, without a division per qword
      Tick enter = arrive;
      if (slot > arrive) {
        enter = slot;
        free_ = stalls_.defer(slot);
      } else {
        free_ = arrive;
      }
      t = std::max(request, enter);
      slot = t;
      ++read_;
    }
    return t;
  }
  Tick free() const { return free_; }

 private:
  const DmaStalls& stalls_;
  Tick period_;
  std::size_t depth_;
  std::vector<Tick> pops_;  // when the qword a FIFO depth back was read, by index mod depth
  Tick free_;
  std::uint32_t read_ = 0;
  std::size_t slot_ = 0;
};

}  // namespace

Tick mcCost(const FlowMacroblock& m, const EeFlowCosts& ee) {
  std::int64_t c =
      ee.mc_cycles_per_mb + m.predictions * ee.mc_cycles_per_prediction + m.averaged * ee.mc_average_cycles;
  if (m.bdec && !m.intra) c += ee.residual_add_cycles;
  return fromEeCycles(c);
}

void planFlow(const FlowPicture& f, const IpuParams& p, const EeFlowCosts& ee, const DmaStalls& in,
              const DmaStalls& out, FlowTiming& t) {
  t.spans.clear();
  t.spans.reserve(f.macroblocks.size() * 3 + 1);
  t.commands.clear();
  t.counts = f.header;
  t.eeBusy = 0;
  t.eeWait = 0;
  t.ipuBusy = 0;
  t.outputStalls = 0;
  const Tick vdec = fromEeCycles(ee.vdec_cycles) + p.vdec_cycles;
  const Tick fdec = fromEeCycles(ee.fdec_cycles) + p.fdec_cycles;
  const Tick outPeriod = p.fromipu_cycles_per_qword;
  const auto dout = static_cast<std::size_t>(p.out_fifo_qwords);
  auto eeSpan = [&](Tick begin, Tick end, const char* label) {
    if (end <= begin) return;
    t.spans.push_back({begin, end, 0, label});
    t.eeBusy += end - begin;
  };

  InputFeed feed(p, in, t.arrival);
  Tick e = t.arrival;
  // BCLR of the picture's start (immediate: PCSX2 IPU.cpp [E]), then the headers: FDEC per field,
  // SETIQ per matrix (64 bytes), the default matrices' BCLRs.
  ++t.counts.bclr;
  const Tick header = fromEeCycles(ee.fdec_cycles) * (1 + f.header.bclr + f.header.setiq) + fdec * f.header.fdec +
                      p.bclr_cycles * (1 + f.header.bclr) + p.setiq_cycles * f.header.setiq;
  // The log: each command after the one before, for the cost the sum above charges it.
  Tick at = e;
  auto issue = [&](std::uint32_t word, Tick cost) {
    t.commands.push_back({word, at, at + cost});
    at += cost;
  };
  if (t.recordCommands) {
    const Tick roundTrip = fromEeCycles(ee.fdec_cycles);
    issue(bclrWord(0), roundTrip + p.bclr_cycles);
    for (const std::uint32_t w : f.headerWords) {
      const IpuOpcode op = opcodeOf(w);
      issue(w, op == IpuOpcode::kBclr    ? roundTrip + p.bclr_cycles
               : op == IpuOpcode::kSetiq ? roundTrip + p.setiq_cycles
                                         : fdec);
    }
  }
  eeSpan(e, e + header, "parse");
  e = std::max(e + header, feed.readThrough(f.headerQwords, e));
  if (t.recordCommands && !t.commands.empty()) t.commands.back().end = std::max(t.commands.back().end, e);
  Tick ipuFree = e;
  Tick bdecDone = e;
  Tick fromFree = out.defer(t.arrival);
  std::vector<Tick> takes(dout + 1, t.arrival);  // when output qword y - Dout left, by index mod (Dout + 1)
  Tick lastTake = t.arrival;                     // the latest of `takes` (they only grow)
  // outCount mod (Dout + 1) and (outCount + 1) mod (Dout + 1), stepped instead of divided per qword.
  std::size_t slot = 0;
  std::size_t nextSlot = 1 % (dout + 1);
  std::uint32_t readBefore = f.headerQwords;
  const FlowMacroblock* previous = nullptr;
  for (const FlowMacroblock& m : f.macroblocks) {
    if (bdecDone > e) {  // _MPEG_WaitBDEC: the previous BDEC's output is in scratchpad
      t.eeWait += bdecDone - e;
      e = bdecDone;
    }
    if (!m.skipped) {
      const Tick begin = e;
      if (t.recordCommands && m.wordCount > 0) {
        at = begin;
        for (std::uint32_t k = m.wordsBegin; k < m.wordsBegin + m.wordCount; ++k) {
          const std::uint32_t w = f.macroblockWords[k];
          issue(w, opcodeOf(w) == IpuOpcode::kVdec ? vdec : fdec);
        }
      } else if (t.recordCommands) {
        at = begin;
        const int sliceFdec = m.sliceStart ? std::min<int>(m.fdec, kSliceHeaderFdec) : 0;
        for (int k = 0; k < sliceFdec; ++k) issue(fdecWord(0), fdec);
        for (int k = 0; k < std::min<int>(m.vdec, 2); ++k) issue(vdecWord(0, static_cast<VdecTable>(k)), vdec);
        for (int k = sliceFdec; k < m.fdec; ++k) issue(fdecWord(0), fdec);
        for (int k = 2; k < m.vdec; ++k) issue(vdecWord(0, VdecTable::kMotionCode), vdec);
      }
      e += vdec * m.vdec + fdec * m.fdec + fromEeCycles(ee.mb_cycles);
      // VDEC and FDEC read the macroblock's first bits: they wait for them to be in the FIFO.
      e = std::max(e, feed.readThrough(std::min(m.needQwords, readBefore + 1), begin));
      if (m.bdec) e += fromEeCycles(ee.bdec_issue_cycles);
      eeSpan(begin, e, "parse");
      t.counts.vdec += m.vdec;
      t.counts.fdec += m.fdec;
      if (m.bdec) {
        ++t.counts.bdec;
        const Tick start = std::max(e, ipuFree) + p.idec_start_cycles;
        const Tick decoded = std::max(start + p.mb_base_cycles + p.mb_cycles_per_bit * m.blockBits,
                                      feed.readThrough(m.needQwords, start));
        // The IPU pushes a qword a cycle once there is room; fromIPU writes each to scratchpad.
        Tick q = decoded;
        const bool keepsUp = !t.stepEveryQword && outPeriod >= 0 && outPeriod <= 1 && fromFree <= decoded &&
                             lastTake <= decoded && out.clear(decoded, decoded + kBdecQwords + outPeriod);
        if (keepsUp) {
          // fromIPU keeps up with the pushes (a period of at most one cycle) and has taken every
          // earlier qword, and no stall falls inside: the loop below would find room for every qword
          // and take each the cycle it is pushed. Only the last Dout + 1 takes stay in the ring.
          const int firstKept = std::max(0, kBdecQwords - static_cast<int>(dout + 1));
          slot = (slot + static_cast<std::size_t>(firstKept)) % (dout + 1);
          for (int y = firstKept; y < kBdecQwords; ++y) {
            takes[slot] = decoded + y;
            if (++slot == dout + 1) slot = 0;
          }
          nextSlot = slot + 1 == dout + 1 ? 0 : slot + 1;
          q = decoded + kBdecQwords;
          lastTake = q - 1;
          fromFree = lastTake + outPeriod;
        }
        for (int y = 0; !keepsUp && y < kBdecQwords; ++y) {
          const Tick room = takes[nextSlot];  // qword y - Dout has left
          if (room > q) {
            q = room;
            ++t.outputStalls;
          }
          const Tick resumed = q <= fromFree ? fromFree : out.defer(q);
          lastTake = std::max(q, fromFree);
          takes[slot] = lastTake;
          fromFree = out.defer(resumed + outPeriod);
          q += 1;
          slot = nextSlot;
          if (++nextSlot == dout + 1) nextSlot = 0;
        }
        ipuFree = q;
        bdecDone = fromFree;
        if (t.recordCommands) t.commands.push_back({m.bdecWord, start - p.idec_start_cycles, bdecDone});
        t.spans.push_back({start - p.idec_start_cycles, bdecDone, 1, "bdec"});
        t.ipuBusy += bdecDone - (start - p.idec_start_cycles);
      } else {
        e = std::max(e, feed.readThrough(m.needQwords, e));
      }
      readBefore = m.needQwords;
    }
    if (previous != nullptr) {  // DoMC: the macroblock before, while BDEC of this one runs
      const Tick begin = e;
      e += mcCost(*previous, ee);
      eeSpan(begin, e, "mc");
    }
    previous = &m;
  }
  if (bdecDone > e) {
    t.eeWait += bdecDone - e;
    e = bdecDone;
  }
  if (previous != nullptr) {
    const Tick begin = e;
    e += mcCost(*previous, ee);
    eeSpan(begin, e, "mc");
  }
  // What follows the last macroblock (the next start code) is read and dropped.
  feed.readThrough(f.inQwords, e);
  t.decodeEnd = e;
  t.inFree = feed.free();
  t.ipuFree = ipuFree;
  t.fromFree = fromFree;
  std::stable_sort(t.spans.begin(), t.spans.end(), [](const FlowSpan& a, const FlowSpan& b) {
    return a.end != b.end ? a.end < b.end : a.begin < b.begin;
  });
}

}  // namespace vbim::ipu
