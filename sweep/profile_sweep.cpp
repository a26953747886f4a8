#include "sweep/profile_sweep.hpp"

#include <algorithm>
#include <stdexcept>

#include "iop/params.hpp"
#include "runtime/error.hpp"
#include "runtime/param_table.hpp"

namespace vbim::sweep {

void sortRings(std::vector<RingSize>& rings) {
  std::sort(rings.begin(), rings.end(), [](const RingSize& a, const RingSize& b) {
    return a.bufmax != b.bufmax ? a.bufmax < b.bufmax : a.bankmax < b.bankmax;
  });
}

int parsePopThreshold(const std::string& text) {
  if (text == "auto") return -1;
  int threshold = -1;
  try {
    std::size_t used = 0;
    threshold = std::stoi(text, &used);
    if (used != text.size() || threshold < 0 || threshold > 255) throw std::invalid_argument("range");
  } catch (const std::exception&) {
    throw Error("--pop-threshold '" + text + "': expected auto or 0..255");
  }
  return threshold;
}

void checkStallSearch(const StallSearch& search) {
  if (search.maxStall <= 0 || search.resolution <= 0 || search.settle <= 0)
    throw Error("--max-stall, --resolution and --settle must be positive");
  if (search.maxStall / search.resolution > 100'000)
    throw Error("--max-stall / --resolution is above 100000 steps: choose a coarser --resolution");
}

RingSize parseRingSize(const std::string& text) {
  const auto colon = text.find(':');
  RingSize r;
  try {
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    std::size_t used = 0;
    r.bankmax = std::stoll(text.substr(0, colon), &used);
    if (used != colon) throw std::invalid_argument("bankmax");
    r.bufmax = std::stoll(text.substr(colon + 1), &used);
    if (used != text.size() - colon - 1) throw std::invalid_argument("bufmax");
  } catch (const std::exception&) {
    throw Error("--ring '" + text + "': expected BANKS:SECTORS (ring.bankmax:ring.bufmax_sectors), e.g. 4:32");
  }
  // The ranges `vbim config --check` and `play` apply (iop/params.cpp): a ring they refuse (2 banks
  // deadlock under SDK-ST's hold rule) is refused here too, before any case runs.
  iop::RingParams ring;
  ParamTable table;
  iop::describeParams(table, ring);
  for (const auto& [key, value] : {std::pair<const char*, std::int64_t>{"ring.bankmax", r.bankmax},
                                   std::pair<const char*, std::int64_t>{"ring.bufmax_sectors", r.bufmax}}) {
    const ParamTable::Param* p = table.find(key);
    if (p != nullptr && (static_cast<double>(value) < p->min || static_cast<double>(value) > p->max)) {
      throw Error("--ring '" + text + "': " + key + " = " + std::to_string(value) + " is outside [" +
                  std::to_string(static_cast<std::int64_t>(p->min)) + ", " +
                  std::to_string(static_cast<std::int64_t>(p->max)) + "] (" + p->source + ")");
    }
  }
  if (r.bufmax < r.bankmax)
    throw Error("--ring '" + text + "': ring.bufmax_sectors must be at least ring.bankmax (one sector per bank)");
  return r;
}

using namespace player;

ProfileData runSweep(const SweepPlan& plan, const SweepObserver& observer) {
  ProfileData data;
  data.search = plan.search;
  auto makeCase = [&](const Stream& s, const RingSize& ring, const std::string& policy) {
    Case c;
    c.stream = &s;
    c.config = plan.base;
    c.config.iop.ring.bankmax = ring.bankmax;
    c.config.iop.ring.bufmax_sectors = ring.bufmax;
    c.config.gs.catchup = policy;
    c.seed = plan.seed;
    c.duration = plan.duration;
    c.kernels = plan.kernels;
    return c;
  };
  for (const Stream* s : plan.streams) {
    for (const auto& [planName, faults] : plan.plans) {
      for (const std::string& policy : plan.policies) {
        for (const RingSize& ring : plan.rings) {
          Case c = makeCase(*s, ring, policy);
          c.faults = faults;
          data.sweep.push_back(SweepRun{s->label, ring, planName, policy, runCase(c, true)});
          if (observer.onRun) observer.onRun(data.sweep.back());
        }
      }
    }
    if (!plan.searchStalls) continue;
    for (const std::string& policy : plan.policies) {
      for (const RingSize& ring : plan.rings) {
        for (const Criterion crit : {Criterion::Late, Criterion::Pop}) {
          const Case c = makeCase(*s, ring, policy);
          data.stalls.push_back(StallRow{s->label, ring, policy, crit, longestSurvivableStall(c, plan.search, crit)});
          if (observer.onStall) observer.onStall(data.stalls.back());
        }
      }
    }
  }
  for (const Stream* s : plan.streams) data.streamBytes.emplace_back(s->label, s->file.bytes);
  return data;
}

}  // namespace vbim::sweep
