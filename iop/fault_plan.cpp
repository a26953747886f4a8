#include "iop/fault_plan.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <set>
#include <sstream>

#include "iop/drive.hpp"
#include "iop/sector_source.hpp"

namespace vbim::iop {

const char* toString(Fault::Kind k) {
  switch (k) {
    case Fault::Kind::Stall:
      return "stall";
    case Fault::Kind::ReadError:
      return "read_error";
    case Fault::Kind::SeekAway:
      return "seek_away";
    case Fault::Kind::Contention:
      return "contention";
    case Fault::Kind::RandomStall:
      return "random_stall";
    case Fault::Kind::RandomError:
      return "random_error";
  }
  return "?";
}

Tick parseDuration(std::string_view text) {
  std::size_t i = 0;
  if (!text.empty() && text[0] == '-') throw std::invalid_argument("a time cannot be negative");
  // 12 integer digits and 9 decimals do not fit an int64 numerator: count in 128 bits and refuse
  // what the 64-bit tick counter cannot hold (it used to wrap, or hang the run).
  __int128 num = 0;
  std::int64_t den = 1;
  int intDigits = 0;
  int fracDigits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    if (++intDigits > 12) throw std::invalid_argument("too many digits");
    num = num * 10 + (text[i++] - '0');
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      if (++fracDigits > 9) throw std::invalid_argument("more than 9 decimals");
      num = num * 10 + (text[i++] - '0');
      den *= 10;
    }
  }
  if (intDigits + fracDigits == 0) throw std::invalid_argument("expected a number followed by s, ms or us");
  const std::string_view unit = text.substr(i);
  if (unit == "s") {
  } else if (unit == "ms") {
    den *= 1000;
  } else if (unit == "us") {
    den *= 1'000'000;
  } else {
    throw std::invalid_argument(unit.empty() ? "missing unit (s, ms or us)"
                                             : "unknown unit '" + std::string(unit) + "' (expected s, ms or us)");
  }
  const __int128 ticks = (2 * num * kBusHz + den) / (2 * static_cast<__int128>(den));  // nearest tick
  if (ticks > kMaxTime) {
    throw std::invalid_argument("longer than the simulated clock can count (at most " +
                                std::to_string(kMaxTime / kBusHz) + "s)");
  }
  return static_cast<Tick>(ticks);
}

Tick contentionSlice(const Fault& f) {
  return static_cast<Tick>(static_cast<__int128>(f.period) * f.share / 100);  // period may be near kMaxTime
}

namespace {

// One entry's commands of another IOP client, made as the clock reaches them: a seek_away is one
// command, a contention entry one hold slice per period.
struct ForeignSeries {
  Fault fault;
  Tick next;         // time of the next command
  Tick periodBegin;  // contention: the period `next` falls in
  Rng rng;           // contention: where in each period the slice is queued
};

// A contention slice is queued at a seeded moment of its period (so that it still fits in it), not
// at the period's start. At a fixed phase, a period equal to the stream's 200 ms re-try after a
// failed sceCdRE (iop/stream_ring.hpp) locks the two clocks: every re-try meets the drive busy and
// the stream never starts (the documented 200 ms example did that from 0 s). A real client's
// requests drift against the stream's; the draw stands for that drift (docs/fault-plans.md, [A]).
Tick sliceTimeIn(Tick periodBegin, const Fault& f, Rng& rng) {
  const Tick periodEnd = std::min(periodBegin + f.period, f.at + f.duration);  // the last may be cut short
  const Tick room = std::max<Tick>(0, periodEnd - periodBegin - contentionSlice(f));
  return periodBegin + static_cast<Tick>(rng.below(static_cast<std::uint64_t>(room) + 1));
}

std::shared_ptr<DriveCommand> foreignCommand(const Fault& f) {
  auto c = std::make_shared<DriveCommand>();
  c->foreign = true;
  c->lsn = f.lba;
  if (f.kind == Fault::Kind::SeekAway) {
    c->sectors = f.sectors;
  } else {
    c->kind = DriveCommand::Kind::Hold;
    c->holdFor = contentionSlice(f);
  }
  return c;
}

// Another IOP client: at each command's time it waits for the drive and issues the command. The
// series are merged by time, ties in plan order (a heap of one entry per series: log time per
// command, memory per entry, not per command).
Task<void> foreignClient(Scheduler& s, Drive& drive, std::vector<ForeignSeries> series) {
  using Head = std::pair<Tick, std::size_t>;  // (time, index in plan order)
  std::priority_queue<Head, std::vector<Head>, std::greater<>> heads;
  for (std::size_t i = 0; i < series.size(); ++i) heads.emplace(series[i].next, i);
  while (!heads.empty()) {
    const auto [at, i] = heads.top();
    heads.pop();
    co_await s.until(at);
    const Fault& f = series[i].fault;
    drive.enqueue(foreignCommand(f));
    ForeignSeries& next = series[i];
    if (f.kind == Fault::Kind::Contention && next.periodBegin + f.period < f.at + f.duration) {
      next.periodBegin += f.period;
      next.next = sliceTimeIn(next.periodBegin, f, next.rng);
      heads.emplace(next.next, i);
    }
  }
}

// random_stall: gaps uniform in [0, 2 x mean) drawn from this entry's own stream, one stall at a
// time as the drive asks for it.
std::function<std::optional<Drive::StallSpan>()> randomStalls(const Fault& f, Rng r) {
  return [f, r, t = f.at]() mutable -> std::optional<Drive::StallSpan> {
    t += static_cast<Tick>(r.below(static_cast<std::uint64_t>(2 * f.meanInterval)));
    if (t >= f.at + f.duration) return std::nullopt;
    const Drive::StallSpan st{t, t + f.stallLength};
    t += f.stallLength;
    return st;
  };
}

}  // namespace

void applyFaults(Scheduler& s, Drive& drive, const FaultPlan& plan, Rng rng) {
  std::vector<ForeignSeries> foreign;
  int index = 0;
  for (const Fault& f : plan.faults) {
    ++index;
    switch (f.kind) {
      case Fault::Kind::Stall:
        drive.addStall(f.at, f.at + f.duration);
        break;
      case Fault::Kind::ReadError:
        drive.addSectorFault(f.lba, f.attempts, f.at);
        break;
      case Fault::Kind::RandomError:
        drive.addRandomErrors(f.at, f.at + f.duration, f.perMillion, f.attempts);
        break;
      case Fault::Kind::RandomStall:
        drive.addStallSeries(randomStalls(f, rng.fork("faults.random_stall." + std::to_string(index))));
        break;
      case Fault::Kind::SeekAway:
      case Fault::Kind::Contention:
        if (f.kind == Fault::Kind::SeekAway) {
          foreign.push_back({f, f.at, f.at, Rng(0)});
        } else if (f.duration > 0) {
          Rng r = rng.fork("faults.contention." + std::to_string(index));
          const Tick first = sliceTimeIn(f.at, f, r);
          foreign.push_back({f, first, f.at, r});
        }
        break;
    }
  }
  if (!foreign.empty()) s.spawn("faults", foreignClient(s, drive, std::move(foreign)));
}

}  // namespace vbim::iop
