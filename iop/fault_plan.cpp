#include "iop/fault_plan.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "iop/drive.hpp"
#include "iop/sector_source.hpp"

namespace vbim::iop {

const char* toString(Fault::Kind k) {
  switch (k) {
    case Fault::Kind::stall:
      return "stall";
    case Fault::Kind::read_error:
      return "read_error";
    case Fault::Kind::seek_away:
      return "seek_away";
    case Fault::Kind::contention:
      return "contention";
    case Fault::Kind::random_stall:
      return "random_stall";
    case Fault::Kind::random_error:
      return "random_error";
  }
  return "?";
}

Tick parseDuration(std::string_view text) {
  std::size_t i = 0;
  if (!text.empty() && text[0] == '-') throw std::invalid_argument("a time cannot be negative");
  std::int64_t num = 0;
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
  return fromSecondsRational(num, den);
}

namespace {

struct ForeignEvent {
  Tick at;
  std::shared_ptr<DriveCommand> cmd;
};

// Another IOP client: at each event's time it waits for the drive and issues its command.
Task<void> foreignClient(Scheduler& s, Drive& drive, std::vector<ForeignEvent> events) {
  for (ForeignEvent& e : events) {
    co_await s.until(e.at);
    drive.enqueue(e.cmd);
  }
}

}  // namespace

void applyFaults(Scheduler& s, Drive& drive, const FaultPlan& plan, Rng rng) {
  std::vector<ForeignEvent> events;
  int index = 0;
  for (const Fault& f : plan.faults) {
    ++index;
    switch (f.kind) {
      case Fault::Kind::stall:
        drive.addStall(f.at, f.at + f.duration);
        break;
      case Fault::Kind::read_error:
        drive.addSectorFault(f.lba, f.attempts, f.at);
        break;
      case Fault::Kind::random_error:
        drive.addRandomErrors(f.at, f.at + f.duration, f.perMillion, f.attempts);
        break;
      case Fault::Kind::random_stall: {
        // Gaps uniform in [0, 2 x mean): integer draws from this entry's own stream.
        Rng r = rng.fork("faults.random_stall." + std::to_string(index));
        Tick t = f.at;
        for (;;) {
          t += static_cast<Tick>(r.below(static_cast<std::uint64_t>(2 * f.meanInterval)));
          if (t >= f.at + f.duration) break;
          drive.addStall(t, t + f.stallLength);
          t += f.stallLength;
        }
        break;
      }
      case Fault::Kind::seek_away: {
        auto c = std::make_shared<DriveCommand>();
        c->lsn = f.lba;
        c->sectors = f.sectors;
        c->foreign = true;
        events.push_back({f.at, c});
        break;
      }
      case Fault::Kind::contention:
        for (Tick t = f.at; t < f.at + f.duration; t += f.period) {
          auto c = std::make_shared<DriveCommand>();
          c->kind = DriveCommand::Kind::hold;
          c->holdFor = f.period * f.share / 100;
          c->lsn = f.lba;
          c->foreign = true;
          events.push_back({t, c});
        }
        break;
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const ForeignEvent& a, const ForeignEvent& b) { return a.at < b.at; });
  if (!events.empty()) s.spawn("faults", foreignClient(s, drive, std::move(events)));
}

}  // namespace vbim::iop
