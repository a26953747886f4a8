#include "ipu/ipu_unit_timing.hpp"

#include <algorithm>
#include <limits>

namespace vbim::ipu {
namespace {

// Before the first qword: a slot freed "long ago".
constexpr Tick kLongAgo = std::numeric_limits<Tick>::min() / 4;

}  // namespace

std::vector<std::uint8_t> idecRestarts(const std::vector<MacroblockBits>& trace, std::size_t mbs) {
  std::vector<std::uint8_t> restart(mbs, 0);
  std::size_t first = mbs;
  for (const MacroblockBits& m : trace) {
    if (m.sliceStart && m.address < mbs) {
      restart[m.address] = 1;
      first = std::min<std::size_t>(first, m.address);
    }
  }
  if (first < mbs) restart[first] = 0;  // the command's own IDEC
  return restart;
}

bool DmaStalls::add(Tick now, Tick duration) {
  if (!windows_.empty() && now < windows_.back().to) return false;
  windows_.push_back({now, now + std::max<Tick>(duration, 0)});
  return true;
}

Tick DmaStalls::deferSlow(Tick t) const {
  // The last window starting at or before t holds it if t is not past its end.
  auto it = std::upper_bound(windows_.begin(), windows_.end(), t, [](Tick v, const Window& w) { return v < w.from; });
  --it;  // exists: t >= front().from
  return t <= it->to ? it->to : t;
}

bool DmaStalls::clearSlow(Tick from, Tick to) const {
  // Disjoint and in order: the first window not over before `from` is the only candidate.
  auto it = std::partition_point(windows_.begin(), windows_.end(), [&](const Window& w) { return w.to < from; });
  return it == windows_.end() || it->from > to;
}

IpuTimeline::IpuTimeline(const IpuParams& p)
    : p_(p),
      // The internal bit buffer holds qwords taken from the FIFO ahead of the decoder.
      din_(static_cast<std::uint64_t>(p.in_fifo_qwords + p.in_buffer_qwords)),
      dout_(static_cast<std::uint64_t>(p.out_fifo_qwords)) {
  st_.inPops.assign(din_, kLongAgo);
  st_.outTakes.assign(dout_ + 1, kLongAgo);
  outPushes_.assign(dout_ + 1, 0);
}

void IpuTimeline::advanceTo(Tick t) {
  st_.toIpuFree = std::max(st_.toIpuFree, t);
  st_.coreFree = std::max(st_.coreFree, t);
  st_.fromIpuFree = std::max(st_.fromIpuFree, t);
}

void IpuTimeline::plan(CommandTiming& c, const DmaStalls& in, const DmaStalls& out, bool recordQwords) {
  const Tick arrival = c.arrival;
  const Tick inPeriod = p_.toipu_cycles_per_qword;
  const Tick outPeriod = p_.fromipu_cycles_per_qword;
  const std::size_t mbs = c.needQwords.size();
  const int qpr = c.qwordsPerRow;
  const std::uint64_t outTotal = static_cast<std::uint64_t>(mbs) * kRowsPerMacroblock * static_cast<std::uint64_t>(qpr);
  c.mbBegin.assign(mbs, 0);
  c.mbDecoded.assign(mbs, 0);
  c.mbEnd.assign(mbs, 0);
  c.rowStalls.clear();
  c.stalls = 0;
  CommandTiming::Qwords& log = c.qwords;
  log = {};

  // A channel waiting for the command wakes when it arrives; one still busy with the previous
  // command's input takes it when done.
  Tick inFree = arrival > st_.toIpuFree ? in.defer(arrival) : st_.toIpuFree;
  Tick fromFree = arrival > st_.fromIpuFree ? out.defer(arrival) : st_.fromIpuFree;
  Tick lastResume = fromFree;

  // Input: toIPU moves qword x once the FIFO has room (qword x - Din popped), the core pops it.
  Tick* const pops = st_.inPops.data();
  std::uint64_t inSlot = st_.inCount % din_;
  auto popInput = [&](Tick request) {
    const Tick arrive = in.defer(inFree + inPeriod);
    const Tick freed = pops[inSlot];
    Tick enter = arrive;
    if (freed > arrive) {  // the channel waited for room: its qword goes in when one is popped
      enter = freed;
      inFree = in.defer(freed);
    } else {
      inFree = arrive;
    }
    const Tick popped = std::max(request, enter);
    pops[inSlot] = popped;
    if (++inSlot == din_) inSlot = 0;
    if (recordQwords) {
      log.inEnter.push_back(enter);
      log.inLeave.push_back(popped);
    }
    return popped;
  };

  // Output: the core pushes qword y once qword y - Dout was taken; fromIPU takes each in turn.
  const std::uint64_t ring = dout_ + 1;
  Tick* const takes = st_.outTakes.data();
  Tick* const pushes = outPushes_.data();
  std::uint64_t pushSlot = st_.outCount % ring;
  std::uint64_t takeSlot = pushSlot;
  std::uint64_t pushed = 0;
  std::uint64_t taken = 0;
  auto takeOutput = [&] {
    const Tick q = pushes[takeSlot];
    const Tick r = fromFree;
    // Waiting on an empty FIFO, the channel is handed the qword at once and wakes when it may.
    const Tick resumed = q <= r ? r : out.defer(q);
    fromFree = out.defer(resumed + outPeriod);
    lastResume = resumed;
    takes[takeSlot] = std::max(r, q);
    if (recordQwords) {
      log.outEnter.push_back(q);
      log.outLeave.push_back(takes[takeSlot]);
    }
    if (++takeSlot == ring) takeSlot = 0;
    ++taken;
  };
  auto pushOutput = [&](Tick request) {
    while (taken + dout_ <= pushed) takeOutput();
    std::uint64_t older = pushSlot + 1;  // the slot of qword y - Dout
    if (older == ring) older = 0;
    const Tick q = std::max(request, takes[older]);
    pushes[pushSlot] = q;
    pushSlot = older;
    ++pushed;
    return q;
  };

  const bool drainKeepsUp =
      dout_ >= static_cast<std::uint64_t>(qpr) && qpr * outPeriod <= p_.csc_cycles_per_mb / kRowsPerMacroblock;

  // A CSC command from EE memory (the BDEC flow's display frame): every macroblock pops the same
  // number of input qwords at no decode cost and goes through the drain stretch below. Once one
  // leaves the channels and FIFOs as the one before it did, shifted by its own length, each later
  // one repeats it shifted again (the recurrence is max and +, which commute with a shift), as long
  // as no DMA stall reaches the times it reads: the rest of the command follows without stepping
  // its qwords (1,152 macroblocks of 88 qwords each per 512x512 + 256x128 frame). The qword log
  // (recordQwords) is stepped in full.
  const std::uint32_t cscStep = mbs > 0 ? c.needQwords[0] : 0;
  bool repeats = c.csc && drainKeepsUp && !recordQwords && mbs > 2 && cscStep > 0;
  for (std::size_t i = 0; repeats && i < mbs; ++i) {
    repeats = c.restart[i] == 0 && c.needQwords[i] == cscStep * static_cast<std::uint32_t>(i + 1);
  }
  bool haveBefore = false;  // steadyBefore_ holds the state after the macroblock before
  Tick beforeFloor = 0;     // the earliest of that state's times, from which it reads on
  auto steadyState = [&](std::vector<Tick>& s, Tick end) {
    s.clear();
    s.push_back(inFree - end);
    s.push_back(fromFree - end);
    s.push_back(lastResume - end);
    for (std::uint64_t j = 0; j < din_; ++j) s.push_back(pops[(inSlot + j) % din_] - end);
    for (std::uint64_t j = 0; j < ring; ++j) s.push_back(takes[(takeSlot + j) % ring] - end);
  };

  // The core: per macroblock its cost spread over the input qwords it pops, then CSC row by row.
  Tick t = std::max(st_.coreFree, arrival) + (c.csc ? 0 : p_.idec_start_cycles);
  std::uint32_t pulled = 0;
  const Tick restartCycles = p_.slice_restart_cycles + p_.idec_start_cycles;
  for (std::size_t i = 0; i < mbs; ++i) {
    if (c.restart[i] != 0) t += restartCycles;
    c.mbBegin[i] = t;
    const Tick cost = c.csc ? 0 : p_.mb_base_cycles + p_.mb_cycles_per_bit * c.bits[i];
    const std::uint32_t k = c.needQwords[i] - pulled;
    if (k == 0) t += cost;
    // Qword j of k is popped floor(cost * j / k) after the start: steps of cost / k, one more
    // whenever the remainders add up past k (exact integer steps, no division per qword).
    const Tick whole = k == 0 ? 0 : cost / k;
    const Tick rem = k == 0 ? 0 : cost % k;
    Tick carry = 0;
    for (std::uint32_t j = 1; j <= k; ++j) {
      t += whole;
      carry += rem;
      if (carry >= k) {
        carry -= k;
        t += 1;
      }
      t = popInput(t);
      ++pulled;
    }
    c.mbDecoded[i] = t;
    if (drainKeepsUp) {
      // The stretch where no FIFO can block: fromIPU has taken the earlier rows when a row is
      // ready, and drains each row before the next (a row's DMA periods <= its CSC time, and the
      // FIFO holds a row), so row r's qwords go in at its ready time R and out at R + n periods.
      while (taken < pushed) takeOutput();
      const Tick firstRow = t + p_.csc_cycles_per_mb / kRowsPerMacroblock;
      if (fromFree <= firstRow && out.clear(firstRow, t + p_.csc_cycles_per_mb + qpr * outPeriod)) {
        const Tick begin = t;
        const auto perMacroblock = static_cast<std::uint64_t>(kRowsPerMacroblock) * static_cast<std::uint64_t>(qpr);
        // Only the last `ring` takes stay in the ring; unless every qword is logged, the earlier
        // ones are skipped (64 qwords per macroblock against a ring of Dout + 1, 9 by default).
        const std::uint64_t skip = recordQwords || perMacroblock <= ring ? 0 : perMacroblock - ring;
        takeSlot = (takeSlot + skip) % ring;
        for (std::uint64_t q = skip; q < perMacroblock; ++q) {
          const auto row = static_cast<Tick>(q / static_cast<std::uint64_t>(qpr));
          const auto n = static_cast<Tick>(q % static_cast<std::uint64_t>(qpr));
          const Tick ready = begin + p_.csc_cycles_per_mb * (row + 1) / kRowsPerMacroblock;
          takes[takeSlot] = ready + n * outPeriod;
          if (recordQwords) {
            log.outEnter.push_back(ready);
            log.outLeave.push_back(ready + n * outPeriod);
          }
          if (++takeSlot == ring) takeSlot = 0;
        }
        t = begin + p_.csc_cycles_per_mb;
        pushed += perMacroblock;
        taken += perMacroblock;
        pushSlot = takeSlot;
        lastResume = t + (qpr - 1) * outPeriod;
        fromFree = t + qpr * outPeriod;
        c.mbEnd[i] = t;
        if (repeats) {
          steadyState(steadyNow_, t);
          if (haveBefore && steadyNow_ == steadyBefore_ && in.clearFrom(beforeFloor) && out.clearFrom(beforeFloor)) {
            const Tick period = t - c.mbEnd[i - 1];
            const std::uint64_t left = mbs - 1 - i;
            for (std::size_t j = i + 1; j < mbs; ++j) {
              const Tick shift = period * static_cast<Tick>(j - i);
              c.mbBegin[j] = c.mbBegin[i] + shift;
              c.mbDecoded[j] = c.mbDecoded[i] + shift;
              c.mbEnd[j] = c.mbEnd[i] + shift;
            }
            t += period * static_cast<Tick>(left);
            inFree = t + steadyNow_[0];
            fromFree = t + steadyNow_[1];
            lastResume = t + steadyNow_[2];
            inSlot = (inSlot + left * cscStep) % din_;
            takeSlot = (takeSlot + left * perMacroblock) % ring;
            pushSlot = takeSlot;
            for (std::uint64_t j = 0; j < din_; ++j) pops[(inSlot + j) % din_] = t + steadyNow_[3 + j];
            for (std::uint64_t j = 0; j < ring; ++j) takes[(takeSlot + j) % ring] = t + steadyNow_[3 + din_ + j];
            pulled += static_cast<std::uint32_t>(left) * cscStep;
            pushed += left * perMacroblock;
            taken += left * perMacroblock;
            break;
          }
          std::swap(steadyNow_, steadyBefore_);
          haveBefore = true;
          beforeFloor = std::min({inFree, fromFree, t});
        }
        continue;
      }
    }
    haveBefore = false;
    for (int row = 0; row < kRowsPerMacroblock; ++row) {
      t += p_.csc_cycles_per_mb * (row + 1) / kRowsPerMacroblock - p_.csc_cycles_per_mb * row / kRowsPerMacroblock;
      const Tick ready = t;
      for (int n = 0; n < qpr; ++n) t = pushOutput(t);
      if (t != ready) {
        ++c.stalls;
        c.rowStalls.push_back({static_cast<std::uint32_t>(i), ready, t});
      }
    }
    c.mbEnd[i] = t;
  }
  // Bytes after the last macroblock (stuffing, the next start code) are read and dropped.
  while (pulled < c.inQwords) {
    t = popInput(t);
    ++pulled;
  }
  while (taken < outTotal) takeOutput();

  c.lastResume = lastResume;
  c.finished = fromFree;
  c.quietAfter = std::max({fromFree, t, inFree});
  st_.toIpuFree = inFree;
  st_.coreFree = t;
  st_.fromIpuFree = fromFree;
  st_.inCount += c.inQwords;
  st_.outCount += outTotal;
}

}  // namespace vbim::ipu
