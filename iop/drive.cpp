#include "iop/drive.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "iop/cd_errors.hpp"

namespace vbim::iop {

const char* toString(SeekClass c) {
  switch (c) {
    case SeekClass::Buffered:
      return "buffered";
    case SeekClass::Contiguous:
      return "contiguous";
    case SeekClass::Fast:
      return "fast";
    case SeekClass::Full:
      return "full";
  }
  return "?";
}

Drive::Drive(Scheduler& s, SectorSource& disc, const DriveParams& p, Rng rng, Tracer* tracer)
    : s_(s),
      disc_(disc),
      p_(p),
      latencyRng_(rng.fork("drive.latency")),
      errorRng_(rng.fork("drive.errors")),
      tracer_(tracer),
      wake_(s),
      idle_(s),
      spinning_(p.initially_spinning) {
  if (tracer_ != nullptr) {
    track_ = tracer_->track("drive");
    dmaTrack_ = tracer_->track("drive.dma");
  }
  proc_ = &s_.spawn("drive", run());
}

// --- the model's arithmetic -------------------------------------------------------------------

Tick Drive::sectorTicks(std::int64_t lsn) const {
  if (p_.spindle == "clv") {
    return static_cast<Tick>((2 * kBusHz + p_.clv_sectors_per_s) / (2 * p_.clv_sectors_per_s));
  }
  // P-CDVD CAV: rate = outer x (inner% + (100 - inner%) x LSN / layer), linear in LSN.
  const __int128 layer = p_.layer_sectors;
  const __int128 pos = std::clamp<std::int64_t>(lsn, 0, p_.layer_sectors);
  const __int128 num = static_cast<__int128>(kBusHz) * 100 * layer;
  const __int128 den = static_cast<__int128>(p_.cav_outer_sectors_per_s) *
                       (p_.cav_inner_percent * layer + (100 - p_.cav_inner_percent) * pos);
  return static_cast<Tick>((2 * num + den) / (2 * den));
}

Tick Drive::revolutionTicks() const {
  return fromUs(p_.revolution_us);
}

Tick Drive::seekTicks(SeekClass c) const {
  switch (c) {
    case SeekClass::Fast:
      return fromUs(p_.fast_seek_us);
    case SeekClass::Full:
      return fromUs(p_.full_seek_us);
    default:
      return 0;
  }
}

Tick Drive::dmaTicks() const {
  return fromIopCycles(p_.dma_iop_cycles_per_sector);
}

SeekClass Drive::classify(std::int64_t from, std::int64_t to) const {
  const std::int64_t d = to - from;
  // Forward jumps inside the window are read through; the head cannot read backwards, so any
  // backward jump is a seek (P-CDVDi uses |d| < 16 for both directions; see docs/timing/iop.md).
  if (d >= 0 && d < p_.contiguous_window_sectors) return SeekClass::Contiguous;
  const std::int64_t ad = d < 0 ? -d : d;
  return ad < p_.fast_seek_window_sectors ? SeekClass::Fast : SeekClass::Full;
}

// --- commands ---------------------------------------------------------------------------------

bool Drive::tryIssue(std::shared_ptr<DriveCommand> c) {
  if (busy()) return false;
  enqueue(std::move(c));
  return true;
}

void Drive::enqueue(std::shared_ptr<DriveCommand> c) {
  c->issuedAt = s_.now();
  c->done = false;
  queue_.push_back(std::move(c));
  wake_.notify();
}

void Drive::abort(DriveCommand& c) {
  if (c.done) return;
  c.aborted = true;
  c.error = kCdErAbort;
  c.done = true;
  c.finishedAt = s_.now();
  if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "break");
  if (c.notify != nullptr) c.notify->notify();
}

Task<void> Drive::sync() {
  while (busy()) co_await idle_.wait();
}

void Drive::finish(DriveCommand& c) {
  if (c.error != 0) ++stats_.errors;
  if (c.done) return;  // aborted earlier: the issuer already has its answer
  c.done = true;
  c.finishedAt = s_.now();
  if (c.notify != nullptr) c.notify->notify();
}

Task<void> Drive::run() {
  for (;;) {
    while (queue_.empty()) co_await wake_.wait();
    running_ = queue_.front();
    queue_.pop_front();
    ++stats_.commands;
    co_await execute(*running_);
    running_.reset();
    lastEnd_ = s_.now();
    if (queue_.empty()) idle_.notify();
  }
}

Task<void> Drive::execute(DriveCommand& c) {
  if (c.aborted) co_return;
  co_await waitOutStall();
  if (c.kind == DriveCommand::Kind::Hold) {
    // Another client has the drive: it ends somewhere else, so the next read of ours seeks.
    co_await work(c.holdFor, "other client");
    if (c.lsn >= 0) head_ = c.lsn;
    headValid_ = false;
    finish(c);
    co_return;
  }
  co_await executeRead(c);
}

void Drive::busySpan(Tick begin, Tick end, std::string_view what) {
  busy_ += end - begin;
  if (tracer_ != nullptr) tracer_->span(track_, begin, end, what);
}

void Drive::closeReadStretch() {
  if (readLabel_ != nullptr && s_.now() > readStretchBegin_) busySpan(readStretchBegin_, s_.now(), readLabel_);
  readStretchBegin_ = s_.now();
}

Tick Drive::busyTime(Tick at) const {
  // Only a stall's span is recorded before it ends; the part after `at` is not busy yet.
  const Tick ahead = openStallEnd_ - std::max(at, openStallBegin_);
  return busy_ - std::clamp<Tick>(ahead, 0, openStallEnd_ - openStallBegin_);
}

Task<void> Drive::waitOutStall() {
  for (;;) {
    refreshStalls();
    Tick until = -1;
    auto it = stalls_.upper_bound(s_.now());
    if (it != stalls_.begin() && s_.now() < std::prev(it)->second) until = std::prev(it)->second;
    if (until < 0) co_return;
    closeReadStretch();
    busySpan(s_.now(), until, "stall");
    openStallBegin_ = s_.now();
    openStallEnd_ = until;
    stats_.stalled += until - s_.now();
    co_await s_.until(until);
    readStretchBegin_ = s_.now();  // a read under way goes on after the stall
  }
}

// Mechanism work of duration d, frozen during stalls: the part that overlaps a stall resumes
// when the stall ends.
Task<void> Drive::work(Tick d, std::string_view what) {
  Tick remaining = d;
  while (remaining > 0) {
    co_await waitOutStall();
    const auto next = stalls_.upper_bound(s_.now());
    const Tick nextStall = next == stalls_.end() ? kNever : next->first;
    const Tick step = std::min(remaining, nextStall - s_.now());
    const Tick begin = s_.now();
    co_await s_.delay(step);
    if (!what.empty()) busySpan(begin, s_.now(), what);
    remaining -= step;
  }
}

Tick Drive::stallOverlap(Tick from, Tick to) {
  refreshStalls();
  Tick sum = 0;
  auto it = stalls_.upper_bound(from);
  if (it != stalls_.begin()) --it;
  for (; it != stalls_.end() && it->first < to; ++it)
    sum += std::max<Tick>(0, std::min(to, it->second) - std::max(from, it->first));
  return sum;
}

void Drive::refreshStalls() {
  const Tick now = s_.now();
  for (StallSeries& series : stallSeries_) {
    while (!series.ended && series.lastBegin <= now) {
      const std::optional<StallSpan> st = series.next();
      if (!st) {
        series.ended = true;
        break;
      }
      series.lastBegin = st->begin;
      addStall(st->begin, st->end);
    }
  }
  // Queries look at the clock and after, and back to when the drive last went idle; a stall from
  // a series always begins after the last query, so a forgotten one can never need merging.
  const Tick horizon = std::min(now, lastEnd_);
  while (!stalls_.empty() && stalls_.begin()->second < horizon) stalls_.erase(stalls_.begin());
}

std::int64_t Drive::readAheadSectors(Tick idle) const {
  if (!spinning_ || !headValid_) return 0;
  std::int64_t n = 0;
  Tick t = 0;
  while (n < p_.read_ahead_sectors && head_ + n < disc_.sectorCount()) {
    t += sectorTicks(head_ + n);
    if (t > idle) break;
    ++n;
  }
  return n;
}

bool Drive::attemptFails(std::int64_t lba) {
  auto it = sectorFaults_.find(lba);
  if (it != sectorFaults_.end() && s_.now() >= it->second.from && it->second.attempts > 0) {
    if (--it->second.attempts == 0) sectorFaults_.erase(it);
    return true;
  }
  // Random errors: one draw per attempt, only while a window (or the base rate) applies, so a
  // clean run makes no draws at all.
  std::int64_t ppm = 0;
  std::int64_t attempts = 1;
  if (p_.sector_error_ppm > 0) ppm = p_.sector_error_ppm;
  for (const RandomErrors& r : randomErrors_) {
    if (s_.now() >= r.from && s_.now() < r.to) {
      ppm = r.ppm;
      attempts = r.attempts;
    }
  }
  if (ppm > 0 && errorRng_.chance(static_cast<std::uint64_t>(ppm), 1'000'000)) {
    if (attempts > 1) sectorFaults_[lba] = SectorFault{attempts - 1, 0};
    return true;
  }
  return false;
}

Task<void> Drive::executeRead(DriveCommand& c) {
  const std::int64_t end = disc_.sectorCount();
  if (c.lsn < 0 || c.lsn >= end) {
    // P-CDVD: an LSN past the last sector is refused at issue with a read error.
    c.error = kCdErRead;
    finish(c);
    co_return;
  }
  // Read-ahead gathered while idle (stall time does not count).
  const Tick now0 = s_.now();
  const Tick idle = now0 - lastEnd_ - stallOverlap(lastEnd_, now0);
  const std::int64_t buffered = readAheadSectors(idle);

  if (!spinning_) {
    ++stats_.spinUps;
    co_await work(fromMs(p_.spin_up_ms), "spin-up");
    spinning_ = true;
    headValid_ = false;
  }
  std::int64_t hits = 0;
  if (headValid_ && c.lsn >= head_ && c.lsn < head_ + buffered) {
    c.seek = SeekClass::Buffered;
    hits = std::min(head_ + buffered - c.lsn, c.sectors);
  } else {
    const std::int64_t from = head_ + buffered;
    c.seek = classify(from, c.lsn);
    if (c.seek == SeekClass::Contiguous) {
      // Read through the gap: those sectors pass under the head.
      Tick skip = 0;
      for (std::int64_t l = from; l < c.lsn; ++l) skip += sectorTicks(l);
      co_await work(skip, "skip");
    } else {
      co_await work(seekTicks(c.seek), c.seek == SeekClass::Fast ? "seek fast" : "seek full");
      co_await work(static_cast<Tick>(latencyRng_.below(static_cast<std::uint64_t>(revolutionTicks()))), "latency");
    }
  }
  ++stats_.seeks[static_cast<int>(c.seek)];
  headValid_ = true;
  head_ = c.seek == SeekClass::Buffered ? head_ + buffered : c.lsn;

  std::array<std::uint8_t, kSectorBytes> scratch{};
  Tick dmaFree = s_.now();
  Tick dmaFirst = -1;
  // The read's span, cut where a retry or a stall begins (they have their own) and resumed after.
  readLabel_ = c.foreign ? "read other" : "read";
  readStretchBegin_ = s_.now();
  for (std::int64_t i = 0; i < c.sectors && !c.aborted; ++i) {
    const std::int64_t lba = c.lsn + i;
    if (lba >= end) {
      c.error = kCdErEndOfMedia;
      break;
    }
    if (i < hits) {
      ++stats_.bufferedHits;
    } else {
      co_await work(sectorTicks(lba), "");
      std::int64_t retries = 0;
      bool failed = false;
      while (attemptFails(lba)) {
        if (retries == maxRetries()) {
          failed = true;
          break;
        }
        ++retries;
        ++stats_.retries;
        closeReadStretch();
        const char* label = std::exchange(readLabel_, nullptr);  // a stall in the retry is the retry's
        co_await work(revolutionTicks(), "retry");
        readLabel_ = label;
        readStretchBegin_ = s_.now();
      }
      ++stats_.sectorsRead;
      head_ = lba + 1;
      if (failed) {
        c.error = kCdErRead;
        break;
      }
    }
    std::uint8_t* out = c.dest != nullptr ? c.dest + i * static_cast<std::int64_t>(kSectorBytes) : scratch.data();
    const SectorReadResult r = disc_.read(lba, SectorSpan(out, kSectorBytes));
    if (!r.ok) throw DiscError(r.error);
    // Drive -> IOP RAM DMA (IOP ch3) overlaps the next sector's read.
    const Tick dmaStart = std::max(s_.now(), dmaFree);
    dmaFree = dmaStart + dmaTicks();
    if (dmaFirst < 0) dmaFirst = dmaStart;
    ++c.sectorsDone;
  }
  closeReadStretch();
  readLabel_ = nullptr;
  if (tracer_ != nullptr && dmaFirst >= 0) tracer_->span(dmaTrack_, dmaFirst, dmaFree, c.foreign ? "dma other" : "dma");
  if (hits > 0 && c.sectors <= hits) head_ = c.lsn + c.sectors;
  co_await s_.until(dmaFree);
  finish(c);
}

// --- faults -----------------------------------------------------------------------------------

void Drive::addStall(Tick begin, Tick end) {
  if (end <= begin) return;
  // Merge with every stored stall it overlaps or touches: the one before it, and those after.
  auto it = stalls_.upper_bound(begin);
  if (it != stalls_.begin() && std::prev(it)->second >= begin) {
    --it;
    begin = it->first;
    end = std::max(end, it->second);
    it = stalls_.erase(it);
  }
  while (it != stalls_.end() && it->first <= end) {
    end = std::max(end, it->second);
    it = stalls_.erase(it);
  }
  stalls_.emplace_hint(it, begin, end);
}

void Drive::addStallSeries(std::function<std::optional<StallSpan>()> next) {
  stallSeries_.push_back(StallSeries{std::move(next)});
}

void Drive::addSectorFault(std::int64_t lba, std::int64_t attempts, Tick from) {
  if (attempts > 0) sectorFaults_[lba] = SectorFault{attempts, from};
}

void Drive::addRandomErrors(Tick from, Tick to, std::int64_t ppm, std::int64_t attempts) {
  randomErrors_.push_back(RandomErrors{from, to, ppm, std::max<std::int64_t>(attempts, 1)});
}

}  // namespace vbim::iop
