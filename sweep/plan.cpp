#include "sweep/plan.hpp"

#include <algorithm>

namespace vbim::sweep {

using namespace player;

const char* toString(Measure m) {
  switch (m) {
    case Measure::FramesLate:
      return "frames_late";
    case Measure::FramesDropped:
      return "frames_dropped";
    case Measure::FramesCaughtUp:
      return "frames_caught_up";
    case Measure::PopMax:
      return "pop_max";
    case Measure::LagMax:
      return "lag_max";
    case Measure::RingOccupancy:
      return "ring_occupancy";
    case Measure::SurvivableStall:
      return "survivable_stall";
    case Measure::Coding:
      return "coding";
    case Measure::BusyShare:
      return "busy_share";
  }
  return "?";
}

std::vector<PlanCase> expandPlan(const SweepPlanSpec& p) {
  std::vector<PlanCase> cases;
  PlanCase c;
  for (c.stream = 0; c.stream < p.streams.size(); ++c.stream) {
    for (c.platform = 0; c.platform < p.platforms.size(); ++c.platform) {
      for (c.faults = 0; c.faults < p.faults.size(); ++c.faults) {
        for (c.policy = 0; c.policy < p.policies.size(); ++c.policy) {
          for (c.ring = 0; c.ring < p.rings.size(); ++c.ring) {
            for (c.seed = 0; c.seed < p.seeds.size(); ++c.seed) {
              for (c.draw = 0; c.draw < p.faults[c.faults].draws.size(); ++c.draw) {
                c.number = cases.size();
                cases.push_back(c);
              }
            }
          }
        }
      }
    }
  }
  return cases;
}

std::pair<std::size_t, std::size_t> shardRange(std::size_t cases, std::size_t k, std::size_t n) {
  return {cases * (k - 1) / n, cases * k / n};
}

bool hasMeasure(const SweepPlanSpec& plan, Measure m) {
  return std::find(plan.measures.begin(), plan.measures.end(), m) != plan.measures.end();
}

}  // namespace vbim::sweep
