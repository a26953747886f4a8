#include "sweep/runner.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace vbim::sweep {

using namespace player;

CaseRecord runPlanCase(const SweepPlanSpec& plan, const PlanCase& pc, const Stream& stream, const Kernels& kernels) {
  CaseRecord r;
  r.number = pc.number;
  Case c;
  c.stream = &stream;
  c.config = plan.platforms[pc.platform].config;
  c.config.iop.ring.bankmax = plan.rings[pc.ring].bankmax;
  c.config.iop.ring.bufmax_sectors = plan.rings[pc.ring].bufmax;
  c.config.gs.catchup = plan.policies[pc.policy];
  c.faults = plan.faults[pc.faults].draws[pc.draw].plan;
  c.seed = pc.runSeed(plan);
  c.duration = plan.duration;
  c.reference = hasMeasure(plan, Measure::LagMax);  // the fault-free reference costs a second pipeline
  c.kernels = kernels;
  r.result = runCase(c, false);
  if (hasMeasure(plan, Measure::SurvivableStall)) r.stall = longestSurvivableStall(c, plan.search, plan.stallCriterion);
  return r;
}

std::vector<CaseRecord> runPlanCases(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                     const StreamOpener& open, const RunOptions& options, const CaseDone& done) {
  std::vector<CaseRecord> records(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex doneMutex;
  auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < cases.size();) {
      CaseRecord r;
      try {
        const std::shared_ptr<Stream> s = open(cases[i].stream);
        r = runPlanCase(plan, cases[i], *s, options.kernels);
      } catch (const std::exception& e) {
        r = CaseRecord{};
        r.number = cases[i].number;
        r.ok = false;
        r.error = e.what();
      }
      records[i] = std::move(r);
      if (done) {
        const std::lock_guard lock(doneMutex);
        done(records[i]);
      }
    }
  };
  const unsigned threads = std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(cases.size())));
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
  }  // joined: every record written
  return records;
}

}  // namespace vbim::sweep
