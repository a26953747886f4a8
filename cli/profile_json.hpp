// `vbim profile --json` (docs/cli.md, "JSON summaries"): the lines a sweep prints, as JSON.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sweep/profile_sweep.hpp"

namespace vbim::cli {
// `vbim profile --json` (a sweep from discs): every sweep run's and stall search's line, the host
// time and the files written.
std::string profileSummaryJson(const sweep::ProfileData& data, double wallSeconds,
                               const std::vector<std::string>& written);

// `vbim profile --plan P --json`, run here or merged from shards: the plan's summary lines and the
// files written, with the facts of the run (how many cases, jobs and host time; or shards merged).
struct PlanSummary {
  std::vector<std::string> lines;  // sweep::summaryLines
  std::size_t cases = 0;
  unsigned jobs = 0;        // run here: the jobs; 0 for a merge
  double wallSeconds = -1;  // run here: the host time; < 0 for a merge
  std::size_t shards = 0;   // merged: the shards joined; 0 for a run here
  std::vector<std::string> written;
};
std::string planSummaryJson(const PlanSummary& s);

}  // namespace vbim::cli
