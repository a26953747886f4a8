// The host a sweep plan runs on: how many cases run at once (`vbim profile --jobs`), and what one
// case costs here in host time and memory, which sizes a Slurm job array (study.hpp). Host time is
// measured, never hashed: no result depends on it.
#pragma once

#include <functional>
#include <string>

#include "sweep/outputs/study.hpp"

namespace vbim::sweep {

// Cores this process may run on (a Slurm task or taskset sees fewer than the machine has).
unsigned coresAvailable();

struct Jobs {
  unsigned jobs = 1;
  std::string warning;  // non-empty when more jobs were asked for than there are cores
};

// `requested` cases at once, or the cores available (up to 64) when it is 0. Throws vbim::Error above
// 64.
Jobs jobsFor(unsigned requested);

struct CaseCost {
  double seconds = 0;  // host seconds of the slowest case of costSample(p.cases)
  double rssMb = 0;    // the process's peak memory after them
};

// Runs each case of costSample(p.cases) through `run` (the caller's, which may show progress), one
// by one, and measures them.
CaseCost measureCaseCost(const LoadedPlan& p, const std::function<void(const PlanCase&)>& run);

}  // namespace vbim::sweep
