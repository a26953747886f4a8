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
  // The first exception that is not a case's own failure: one out of `done` (its progress report saw
  // Ctrl-C, cli/interrupt.hpp) or a non-std exception from a case. It must not leave a worker thread
  // (std::terminate); it stops the sweep and is rethrown on the calling thread once all have joined.
  std::exception_ptr stopped;
  std::atomic<bool> stop{false};
  const auto stopWith = [&](std::exception_ptr e) {
    const std::lock_guard lock(doneMutex);
    if (!stopped) stopped = std::move(e);
    stop = true;
  };
  auto work = [&] {
    for (std::size_t i; !stop && (i = next.fetch_add(1)) < cases.size();) {
      CaseRecord r;
      try {
        const std::shared_ptr<Stream> s = open(cases[i].stream);
        r = runPlanCase(plan, cases[i], *s, options.kernels);
      } catch (const std::exception& e) {
        r = CaseRecord{};
        r.number = cases[i].number;
        r.ok = false;
        r.error = e.what();
      } catch (...) {
        stopWith(std::current_exception());
        return;
      }
      records[i] = std::move(r);
      if (done) {
        const std::lock_guard lock(doneMutex);
        if (stop) return;  // no report after the one that stopped the sweep
        try {
          done(records[i]);
        } catch (...) {
          stopped = std::current_exception();  // under the lock, as stopWith
          stop = true;
          return;
        }
      }
    }
  };
  const unsigned threads = std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(cases.size())));
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
  }  // joined: every record written, or the sweep stopped
  if (stopped) std::rethrow_exception(stopped);
  return records;
}

}  // namespace vbim::sweep
