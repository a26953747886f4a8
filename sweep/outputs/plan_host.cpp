#include "sweep/outputs/plan_host.hpp"

#include <sched.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "runtime/error.hpp"

namespace vbim::sweep {

namespace {

constexpr unsigned kMaxJobs = 64;

}  // namespace

unsigned coresAvailable() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

Jobs jobsFor(unsigned requested) {
  const unsigned cores = coresAvailable();
  if (requested == 0) return {std::min(cores, kMaxJobs), ""};
  if (requested > kMaxJobs) {
    throw Error("--jobs " + std::to_string(requested) + ": at most " + std::to_string(kMaxJobs) +
                " (this machine offers " + std::to_string(cores) + " cores)");
  }
  if (requested > cores) {
    return {requested, "--jobs " + std::to_string(requested) + " is more than the " + std::to_string(cores) +
                           " cores available: cases will share cores (no faster, same results)"};
  }
  return {requested, ""};
}

CaseCost measureCaseCost(const LoadedPlan& p, const std::function<void(const PlanCase&)>& run) {
  CaseCost cost;
  for (const PlanCase& c : costSample(p.cases)) {
    const auto t0 = std::chrono::steady_clock::now();
    run(c);
    cost.seconds = std::max(cost.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  cost.rssMb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return cost;
}

}  // namespace vbim::sweep
