#include "runs/profile_json.hpp"

#include <nlohmann/json.hpp>

#include "player/report.hpp"
#include "runs/play_json.hpp"

namespace vbim::runs {

namespace {

using Json = nlohmann::ordered_json;

Json ring(const sweep::RingSize& r) {
  return Json{{"banks", r.bankmax}, {"sectors", r.bufmax}};
}

Json health(const gs::PresenterCounters& lightmap, const player::RunTotals& totals) {
  const player::RunHealth h = player::runHealth(lightmap, totals);
  return Json{{"verdict", h.verdict}, {"stuck_s", toSeconds(h.stuckFor)}};
}

}  // namespace

std::string profileSummaryJson(const sweep::ProfileData& data, double wallSeconds,
                               const std::vector<std::string>& written, bool& replaced) {
  Json runs = Json::array();
  for (const sweep::SweepRun& r : data.sweep) {
    runs.push_back(Json{{"stream", r.stream},
                        {"ring", ring(r.ring)},
                        {"faults", r.faults},
                        {"policy", r.policy},
                        {"frames_late", r.result.lightmap.framesLate},
                        {"pop_max", r.result.pop.value},
                        {"lag_max", r.result.totals.lag.value},
                        {"health", health(r.result.lightmap, r.result.totals)}});
  }
  Json stalls = Json::array();
  for (const sweep::StallRow& s : data.stalls) {
    const sweep::StallResult& res = s.result;
    stalls.push_back(Json{{"stream", s.stream},
                          {"ring", ring(s.ring)},
                          {"policy", s.policy},
                          {"criterion", sweep::toString(s.criterion)},
                          // null: the case fails even without a stall
                          {"longest_s", res.longest ? Json(toSeconds(*res.longest)) : Json(nullptr)},
                          {"at_least", res.saturated},
                          {"runs", res.runs}});
  }
  Json j;
  j["sweep_runs"] = runs;
  j["stall_searches"] = stalls;
  j["host_s"] = wallSeconds;
  j["outputs"] = written;
  return jsonText(j, replaced);
}

std::string planSummaryJson(const sweep::PlanSummary& s, bool& replaced) {
  Json j;
  j["cases"] = s.cases;
  if (s.shards > 0) {
    j["shards_merged"] = s.shards;
  } else {
    j["jobs"] = s.jobs;
    j["host_s"] = s.wallSeconds;
  }
  j["summary"] = s.lines;
  j["outputs"] = s.written;
  return jsonText(j, replaced);
}

}  // namespace vbim::runs
