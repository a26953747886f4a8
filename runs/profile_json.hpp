// `vbim profile --json` (docs/cli.md, "JSON summaries"): the lines a sweep prints, as JSON (jsonText:
// runs/play_json.hpp; `replaced`: bytes of the inputs that were not UTF-8 written as U+FFFD).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sweep/outputs/plan_modes.hpp"
#include "sweep/profile_sweep.hpp"

namespace vbim::runs {
// `vbim profile --json` (a sweep from discs): every sweep run's and stall search's line, the host
// time and the files written.
std::string profileSummaryJson(const sweep::ProfileData& data, double wallSeconds,
                               const std::vector<std::string>& written, bool& replaced);

// `vbim profile --plan P --json`, run here or merged from shards: the plan's summary lines and the
// files written, with the facts of the run (how many cases, jobs and host time; or shards merged).
std::string planSummaryJson(const sweep::PlanSummary& s, bool& replaced);

}  // namespace vbim::runs
