#include "sweep/profile_sweep.hpp"

namespace vbim::sweep {

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
